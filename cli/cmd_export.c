/* cmd_export.c: `mcrash export` */
#include "cli/cli.h"

int cli_export(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "issue #2");
}
