/* cmd_signal.c: `mcrash signal` */
#include "cli/cli.h"

int cli_signal(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "issue #3");
}
