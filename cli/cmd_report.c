/* cmd_report.c: `mcrash report` */
#include "cli/cli.h"

int cli_report(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    return cli_not_built(argv[0], "the HTML report is not built");
}
