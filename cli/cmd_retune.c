/* cmd_retune.c: `mcrash retune` */
#include "cli/cli.h"

int cli_retune(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "stage-3 retune is not built");
}
