/* tests for core/mcs_error: status text, exit codes, first error wins, log handler */
#include "core/mcs_error.h"
#include "tests/harness.h"

static void test_status_text(void)
{
    CHECK(strcmp(mcs_status_str(MCS_OK), "ok") == 0);
    CHECK(strcmp(mcs_status_str(MCS_ERR_UNIT), "bad unit") == 0);
    CHECK(strcmp(mcs_status_str((mcs_status)999), "unknown status") == 0);
}

static void test_exit_codes(void)
{
    CHECK(mcs_status_exit_code(MCS_OK) == 0);
    CHECK(mcs_status_exit_code(MCS_ERR_NUMERIC) == 1);
    CHECK(mcs_status_exit_code(MCS_ERR_YAML) == 2);
    CHECK(mcs_status_exit_code(MCS_ERR_KEY) == 2);
}

static void test_first_error_wins(void)
{
    mcs_error e;
    mcs_error_clear(&e);
    CHECK(MCS_ERR(&e, MCS_ERR_RANGE, "mass: %g kg is negative", -1.0) == MCS_ERR_RANGE);
    MCS_ERR(&e, MCS_ERR_KEY, "second");
    CHECK(e.status == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "mass: -1 kg is negative");
    CHECK(e.where_line > 0);
}

static char last_msg[256];
static int last_lvl = -1;
static void capture(mcs_log_level lvl, const char *msg, void *user)
{
    (void)user;
    last_lvl = (int)lvl;
    snprintf(last_msg, sizeof last_msg, "%s", msg);
}

static void test_log_handler(void)
{
    mcs_log_set_handler(capture, NULL);
    mcs_log(MCS_LOG_WARN, "drift %d %%", 3);
    CHECK(last_lvl == MCS_LOG_WARN);
    CHECK(strcmp(last_msg, "drift 3 %") == 0);
    last_lvl = -1;
    mcs_log(MCS_LOG_DEBUG, "hidden");
    CHECK(last_lvl == -1);
    mcs_log_set_handler(NULL, NULL);
}

int main(void)
{
    RUN(test_status_text);
    RUN(test_exit_codes);
    RUN(test_first_error_wins);
    RUN(test_log_handler);
    TEST_END();
}
