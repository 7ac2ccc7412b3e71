/* cmd_run.c: `mcrash run` */
#include "cli/cli.h"

int cli_run(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "issues #4 and #5");
}
