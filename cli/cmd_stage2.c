/* cmd_stage2.c: `mcrash stage2` */
#include "cli/cli.h"

int cli_stage2(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "stage 2 is not built");
}
