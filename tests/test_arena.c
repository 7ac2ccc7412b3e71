/* tests for core/mcs_arena: alignment, exhaustion as an error, mark/reset, high-water mark */
#include "core/mcs_arena.h"
#include "tests/harness.h"

#include <stdint.h>

static void test_create_destroy(void)
{
    mcs_error e;
    mcs_error_clear(&e);
    mcs_arena *a = NULL;
    CHECK(mcs_arena_create(1024, &a, &e) == MCS_OK);
    CHECK(a != NULL);
    CHECK(mcs_arena_capacity(a) == 1024);
    CHECK(mcs_arena_used(a) == 0);
    mcs_arena_destroy(&a);
    CHECK(a == NULL);
    mcs_arena_destroy(&a); /* destroying NULL is fine */
    CHECK(mcs_arena_create(0, &a, &e) == MCS_ERR_USAGE);
    CHECK(a == NULL);
}

static void test_alignment(void)
{
    mcs_error e;
    mcs_error_clear(&e);
    mcs_arena *a = NULL;
    CHECK(mcs_arena_create(4096, &a, &e) == MCS_OK);
    char *c = mcs_arena_alloc(a, 1, 1, &e);
    CHECK(c != NULL);
    double *d = MCS_ARENA_NEW(a, double, 10, &e);
    CHECK(d && (uintptr_t)d % _Alignof(double) == 0);
    for (int i = 0; i < 10; i++)
        CHECK(d[i] == 0.0); /* zero-filled */
    mcs_arena_alloc(a, 3, 1, &e);
    void *p64 = mcs_arena_alloc(a, 8, 64, &e);
    CHECK(p64 && (uintptr_t)p64 % 64 == 0);
    void *p0 = mcs_arena_alloc(a, 0, 0, &e);
    CHECK(p0 && (uintptr_t)p0 % _Alignof(max_align_t) == 0);
    /* allocations do not overlap: write all, read back */
    *c = 'x';
    for (int i = 0; i < 10; i++)
        d[i] = i;
    memset(p64, 0xab, 8);
    CHECK(*c == 'x' && d[9] == 9.0);
    CHECK(e.status == MCS_OK);
    mcs_arena_destroy(&a);
}

static void test_exhaustion_is_an_error(void)
{
    mcs_error e;
    mcs_error_clear(&e);
    mcs_arena *a = NULL;
    CHECK(mcs_arena_create(100, &a, &e) == MCS_OK);
    CHECK(mcs_arena_alloc(a, 96, 8, &e) != NULL);
    size_t used = mcs_arena_used(a);
    CHECK(mcs_arena_alloc(a, 16, 8, &e) == NULL);
    CHECK(e.status == MCS_ERR_ARENA);
    CHECK_STR_CONTAINS(e.msg, "16 bytes requested");
    CHECK(mcs_arena_used(a) == used); /* a failed request changes nothing */
    /* n * size overflow */
    mcs_error_clear(&e);
    CHECK(mcs_arena_calloc(a, SIZE_MAX / 2, 4, 1, &e) == NULL);
    CHECK(e.status == MCS_ERR_ARENA);
    /* a NULL error pointer is allowed */
    CHECK(mcs_arena_alloc(a, 1000, 1, NULL) == NULL);
    /* exactly filling the block works */
    mcs_arena_reset(a, 0);
    CHECK(mcs_arena_alloc(a, 100, 1, NULL) != NULL);
    CHECK(mcs_arena_used(a) == 100);
    mcs_arena_destroy(&a);
}

static void test_mark_reset_high_water(void)
{
    mcs_error e;
    mcs_error_clear(&e);
    mcs_arena *a = NULL;
    CHECK(mcs_arena_create(1000, &a, &e) == MCS_OK);
    mcs_arena_alloc(a, 100, 1, &e);
    size_t m = mcs_arena_mark(a);
    CHECK(m == 100);
    /* a time loop: each step allocates temporaries and resets to the mark */
    for (int step = 0; step < 1000; step++) {
        size_t n = (size_t)(step % 7) * 50;
        void *p = mcs_arena_alloc(a, n, 1, &e);
        CHECK(p != NULL);
        mcs_arena_reset(a, m);
    }
    CHECK(mcs_arena_used(a) == 100);
    CHECK(mcs_arena_high_water(a) == 100 + 6 * 50); /* largest step: 300 bytes */
    mcs_arena_reset(a, 0);
    CHECK(mcs_arena_used(a) == 0);
    CHECK(mcs_arena_high_water(a) == 400);
    CHECK(e.status == MCS_OK);
    mcs_arena_destroy(&a);
}

int main(void)
{
    RUN(test_create_destroy);
    RUN(test_alignment);
    RUN(test_exhaustion_is_an_error);
    RUN(test_mark_reset_high_water);
    TEST_END();
}
