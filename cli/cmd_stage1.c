/* cmd_stage1.c: `mcrash stage1` */
#include "cli/cli.h"

int cli_stage1(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "issue #4");
}
