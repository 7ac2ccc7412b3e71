/* cmd_injury.c: `mcrash injury` */
#include "cli/cli.h"

int cli_injury(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "issue #3");
}
