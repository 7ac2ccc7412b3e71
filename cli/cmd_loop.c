/* cmd_loop.c: `mcrash loop` */
#include "cli/cli.h"

int cli_loop(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "the stage loop is not built");
}
