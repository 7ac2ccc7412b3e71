/* cmd_study.c: `mcrash study` */
#include "cli/cli.h"

int cli_study(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "studies are not built");
}
