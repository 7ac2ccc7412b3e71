/* tests for the `mcrash` command itself: help, version, unknown and unbuilt subcommands */
#include "tests/cli_util.h"
#include "tests/harness.h"
#include "core/mcs_version.h"

static void test_help_and_version(void)
{
    cli_result *r = cli_run("--help");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "check");
    CHECK_STR_CONTAINS(r->out, "compare");
    r = cli_run("--version");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, MCS_VERSION);
    r = cli_run("help run");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "--stage");
    r = cli_run("");
    CHECK(r->status == 2);
}

static void test_unknown_subcommand(void)
{
    cli_result *r = cli_run("frobnicate");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "unknown subcommand");
    r = cli_run("help frobnicate");
    CHECK(r->status == 2);
}

static void test_unbuilt_says_so(void)
{
    /* study is built (tests/test_study_cli.c): a missing study file is bad input */
    cli_result *r = cli_run("study x.yaml");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "x.yaml");
}

int main(void)
{
    RUN(test_help_and_version);
    RUN(test_unknown_subcommand);
    RUN(test_unbuilt_says_so);
    TEST_END();
}
