/* tests for core/mcs_progress: the text of a line, rate limiting with a fake clock, quiet and
 * non-terminal streams print nothing, the final newline */
#include "core/mcs_progress.h"
#include "tests/harness.h"

/* a fake wall clock: advances `step` seconds per read and counts reads */
typedef struct {
    double now, step;
    long reads;
} fake_clock;

static double fake_read(void *user)
{
    fake_clock *c = user;
    c->reads++;
    double t = c->now;
    c->now += c->step;
    return t;
}

static void test_format(void)
{
    char b[256];
    mcs_progress_format(b, sizeof b, "stage 1", 0.42, 0.084, 0.2, 3.2, 4.42);
    CHECK(strcmp(b, "stage 1   42.0 %  t 84.0 / 200.0 ms  wall 3.2 s  ETA 4.4 s") == 0);
    mcs_progress_format(b, sizeof b, NULL, 0.0, 0.0, 0.15, 0.0123, -1);
    CHECK(strcmp(b, "  0.0 %  t 0.0 / 150.0 ms  wall 12 ms  ETA --") == 0);
    mcs_progress_format(b, sizeof b, "fe", 1.0, 0.15, 0.15, 125.0, 0);
    CHECK_STR_CONTAINS(b, "100.0 %");
    CHECK_STR_CONTAINS(b, "wall 2 min 05 s");
    CHECK_STR_CONTAINS(b, "ETA 0 ms");
    mcs_progress_format(b, sizeof b, "fe", 0.5, 0.1, 0.2, 7380.0, 7380.0);
    CHECK_STR_CONTAINS(b, "wall 2 h 03 min  ETA 2 h 03 min");
}

static int count_char(const char *s, char c)
{
    int n = 0;
    for (; *s; s++)
        n += *s == c;
    return n;
}

/* 20000 steps of 1 ms wall each = 20 s. The clock is read every 64 steps (64 ms), so a redraw
 * happens at the first read >= 200 ms after the last: every 4 reads = 256 ms, i.e.
 * floor(20000 / 256) = 78 redraws, plus the final one: 79 (fewer than 5 per second) */
static void test_rate_limit(void)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    fake_clock fc = {.now = 100.0, .step = 0};
    mcs_progress_opts o = mcs_progress_opts_default();
    o.out = f;
    o.force = 1;
    o.clock = fake_read;
    o.clock_user = &fc;
    o.label = "stage 1";
    mcs_progress p;
    mcs_progress_start(&p, &o, 0.2);
    const int n = 20000;
    for (int i = 1; i <= n; i++) {
        fc.now += 1e-3; /* each step costs 1 ms of wall time */
        mcs_progress_update(&p, 0.2 * i / n);
    }
    long reads = fc.reads;
    mcs_progress_finish(&p, 0.2);
    fclose(f);
    CHECK(reads <= 1 + n / 64);
    CHECK(p.redraws == 79);
    CHECK(count_char(text, '\r') == (int)p.redraws);
    CHECK(count_char(text, '\n') == 1 && text[len - 1] == '\n');
    /* the last line: 100 %, at 20 s of wall time */
    const char *last = strrchr(text, '\r');
    CHECK_STR_CONTAINS(last, "stage 1  100.0 %  t 200.0 / 200.0 ms  wall 20.0 s  ETA 0 ms");
    /* the line drawn half-way (at 39 * 256 ms): the ETA is the elapsed wall time again */
    CHECK_STR_CONTAINS(text, "\rstage 1   49.9 %  t 99.8 / 200.0 ms  wall 10.0 s  ETA 10.0 s\r");
    free(text);
}

/* shorter lines are padded with blanks over a longer previous one */
static void test_padding(void)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    fake_clock fc = {.now = 0, .step = 0};
    mcs_progress_opts o = mcs_progress_opts_default();
    o.out = f;
    o.force = 1;
    o.check_every = 1;
    o.clock = fake_read;
    o.clock_user = &fc;
    mcs_progress p;
    mcs_progress_start(&p, &o, 1.0);
    fc.now = 200.0; /* 1 % after 200 s: "ETA 5 h 30 min" */
    mcs_progress_update(&p, 0.01);
    fc.now = 201.0; /* 99 %: "ETA 2.0 s", a shorter line */
    mcs_progress_update(&p, 0.99);
    fclose(f);
    char *second = strrchr(text, '\r');
    CHECK(second != NULL);
    size_t first_len = (size_t)(second - text) - 1, second_len = strlen(second) - 1;
    CHECK_STR_CONTAINS(text, "ETA 5 h 30 min");
    CHECK_STR_CONTAINS(second, "ETA 2.0 s   ");
    CHECK(second_len == first_len); /* blanks cover the rest of the longer line */
    free(text);
}

static void test_quiet_and_not_a_terminal(void)
{
    fake_clock fc = {.now = 0, .step = 1.0};
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    mcs_progress_opts o = mcs_progress_opts_default();
    o.out = f;
    o.clock = fake_read;
    o.clock_user = &fc;
    mcs_progress p;
    /* a memory stream is not a terminal: nothing, and the clock is never read */
    mcs_progress_start(&p, &o, 1.0);
    CHECK(!p.active);
    for (int i = 0; i < 1000; i++)
        mcs_progress_update(&p, i * 1e-3);
    mcs_progress_finish(&p, 1.0);
    /* forced but quiet: nothing either */
    o.force = 1;
    o.quiet = 1;
    mcs_progress_start(&p, &o, 1.0);
    for (int i = 0; i < 1000; i++)
        mcs_progress_update(&p, i * 1e-3);
    mcs_progress_finish(&p, 1.0);
    fclose(f);
    CHECK(len == 0);
    CHECK(fc.reads == 0);
    free(text);
}

int main(void)
{
    RUN(test_format);
    RUN(test_rate_limit);
    RUN(test_padding);
    RUN(test_quiet_and_not_a_terminal);
    TEST_END();
}
