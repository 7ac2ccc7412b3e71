/* test_report_page: the page of `mcrash report` opened in headless Chromium (Debian package
 * `chromium`; `make deps` installs it as root): a screenshot that is not blank (the fraction of
 * non-white pixels and the spread of their brightness), no message on the browser's console
 * (an SVG attribute Chromium cannot read, a script error), and the DOM it builds holding every
 * <svg> the page has. Both checks are first shown to fail on a page made to fail them (a white
 * page, a path with a NaN). Without Chromium the test says so and skips. */
#include "tests/harness.h"
#include "tests/report_sample.h"
#include "translators/tr_report.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

static char tdir[64];
static char chrome[512];

#define tpath(name) th_path(tdir, (name))

/* the browser: $MCRASH_CHROMIUM, else the first of chromium, chromium-browser on the PATH */
static int find_chromium(void)
{
    const char *env = getenv("MCRASH_CHROMIUM");
    if (env && *env) {
        snprintf(chrome, sizeof chrome, "%s", env);
        return access(chrome, X_OK) == 0;
    }
    const char *names[] = {"chromium", "chromium-browser"};
    for (int i = 0; i < 2; i++) {
        char cmd[128];
        snprintf(cmd, sizeof cmd, "command -v %s 2>/dev/null", names[i]);
        FILE *p = popen(cmd, "r");
        if (!p) continue;
        int ok = fgets(chrome, sizeof chrome, p) != NULL;
        pclose(p);
        chrome[strcspn(chrome, "\n")] = 0;
        if (ok && chrome[0]) return 1;
    }
    return 0;
}

/* run the browser on a page: mode "--screenshot=FILE" or "--dump-dom"; its stdout and stderr
 * into out and log; the exit status */
static int browse(const char *html, const char *mode, const char *out, const char *log)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd,
             "timeout 180 %s --headless --no-sandbox --disable-gpu --hide-scrollbars "
             "--no-first-run --user-data-dir=%s --window-size=1280,2400 "
             "--virtual-time-budget=5000 --enable-logging=stderr --v=0 %s file://%s >%s 2>%s",
             chrome, tpath("profile"), mode, html, out, log);
    return system(cmd);
}

/* lines of the browser's log that are console messages (printed, marked expected or not) */
static int console_messages(const char *log, int expected)
{
    FILE *f = fopen(log, "r");
    char line[4096];
    int n = 0;
    while (f && fgets(line, sizeof line, f))
        if (strstr(line, ":CONSOLE")) {
            fprintf(stderr, "console%s: %s", expected ? " (expected)" : "", line);
            n++;
        }
    if (f) fclose(f);
    return n;
}

static uint32_t be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* an 8-bit RGB or RGBA PNG (no interlace): the fraction of pixels that are not white (a channel
 * below 235) and the standard deviation of the brightness (0..255); 0 when read */
static int png_stats(const char *path, double *nonwhite, double *sd, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)n), *idat = malloc((size_t)n);
    size_t ni = 0;
    int ok = b && idat && fread(b, 1, (size_t)n, f) == (size_t)n && n > 33 &&
             memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0;
    fclose(f);
    int bpp = 0;
    for (long p = 8; ok && p + 12 <= n;) {
        uint32_t len = be32(b + p);
        const unsigned char *type = b + p + 4, *d = b + p + 8;
        if (p + 12 + (long)len > n) break;
        if (!memcmp(type, "IHDR", 4)) {
            *w = (int)be32(d);
            *h = (int)be32(d + 4);
            bpp = d[9] == 6 ? 4 : d[9] == 2 ? 3 : 0;
            ok = d[8] == 8 && bpp && d[12] == 0;
        } else if (!memcmp(type, "IDAT", 4)) {
            memcpy(idat + ni, d, len);
            ni += len;
        }
        p += 12 + (long)len;
    }
    size_t stride = (size_t)*w * (size_t)bpp, raw_n = (stride + 1) * (size_t)*h;
    unsigned char *raw = ok ? malloc(raw_n) : NULL;
    uLongf got = (uLongf)raw_n;
    ok = raw && uncompress(raw, &got, idat, (uLong)ni) == Z_OK && got == raw_n;
    double sum = 0, sum2 = 0, nw = 0;
    for (int y = 0; ok && y < *h; y++) { /* undo the row filters in place */
        unsigned char *row = raw + (size_t)y * (stride + 1) + 1, *up = row - stride - 1;
        int ft = row[-1];
        for (size_t x = 0; x < stride; x++) {
            int a = x >= (size_t)bpp ? row[x - (size_t)bpp] : 0, u = y ? up[x] : 0,
                c = y && x >= (size_t)bpp ? up[x - (size_t)bpp] : 0;
            int add = ft == 1 ? a : ft == 2 ? u : ft == 3 ? (a + u) / 2 : ft == 4 ? paeth(a, u, c)
                                                                                  : 0;
            row[x] = (unsigned char)(row[x] + add);
        }
        for (int x = 0; x < *w; x++) {
            const unsigned char *px = row + (size_t)x * (size_t)bpp;
            double l = 0.299 * px[0] + 0.587 * px[1] + 0.114 * px[2];
            sum += l;
            sum2 += l * l;
            nw += px[0] < 235 || px[1] < 235 || px[2] < 235;
        }
    }
    double np = (double)*w * *h;
    if (ok && np > 0) {
        *nonwhite = nw / np;
        *sd = sqrt(fmax(sum2 / np - (sum / np) * (sum / np), 0));
    }
    free(b);
    free(idat);
    free(raw);
    return ok ? 0 : -1;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* the checks on pages made to fail them: a white page is blank, a NaN in a path is an error */
static void test_checks_fail_on_bad_pages(void)
{
    write_text(tpath("white.html"), "<!DOCTYPE html><html><body></body></html>\n");
    double nonwhite = -1, sd = -1;
    int w = 0, h = 0;
    char mode[600];
    snprintf(mode, sizeof mode, "--screenshot=%s", tpath("white.png"));
    CHECK(browse(tpath("white.html"), mode, tpath("o.txt"), tpath("white.log")) == 0);
    CHECK(png_stats(tpath("white.png"), &nonwhite, &sd, &w, &h) == 0);
    CHECK(w == 1280 && h == 2400);
    CHECK(nonwhite < 0.001 && sd < 1);
    write_text(tpath("nan.html"),
               "<!DOCTYPE html><html><body><svg width=\"50\" height=\"50\"><path "
               "d=\"M0 0L10 nan\" stroke=\"#000\"/></svg></body></html>\n");
    snprintf(mode, sizeof mode, "--screenshot=%s", tpath("nan.png"));
    CHECK(browse(tpath("nan.html"), mode, tpath("o.txt"), tpath("nan.log")) == 0);
    CHECK(console_messages(tpath("nan.log"), 1) >= 1);
}

static void test_report_in_chromium(void)
{
    tr_report_summary sum;
    mcs_error e = {0};
    CHECK(rs_write(tpath("sample.h5")) == 0);
    CHECK(tr_report_write(tpath("sample.h5"), tpath("sample.html"), NULL, &sum, &e) == MCS_OK);
    char mode[600];
    snprintf(mode, sizeof mode, "--screenshot=%s", tpath("sample.png"));
    CHECK(browse(tpath("sample.html"), mode, tpath("o.txt"), tpath("shot.log")) == 0);
    CHECK(console_messages(tpath("shot.log"), 0) == 0);
    double nonwhite = 0, sd = 0;
    int w = 0, h = 0;
    CHECK(png_stats(tpath("sample.png"), &nonwhite, &sd, &w, &h) == 0);
    printf("screenshot %dx%d: %.1f %% of the pixels not white, brightness sd %.1f\n", w, h,
           100 * nonwhite, sd);
    /* the top 2400 px hold the summary, the energies, the injury bars and table and the first
     * dummy plots: a page of text and curves is some percent ink (the white page: 0) */
    CHECK(nonwhite > 0.02);
    CHECK(sd > 10);
    /* the DOM Chromium builds has every <svg> of the page */
    CHECK(browse(tpath("sample.html"), "--dump-dom", tpath("dom.html"), tpath("dom.log")) == 0);
    CHECK(console_messages(tpath("dom.log"), 0) == 0);
    FILE *f = fopen(tpath("dom.html"), "r");
    char line[1 << 16];
    int nsvg = 0;
    while (f && fgets(line, sizeof line, f))
        for (const char *p = line; (p = strstr(p, "<svg ")); p += 5) nsvg++;
    if (f) fclose(f);
    CHECK(nsvg == sum.nsvg);
}

int main(void)
{
    if (!find_chromium()) {
        printf("test_report_page: SKIPPED: Chromium not found (Debian: apt-get install "
               "chromium, which `make deps` does as root; or set MCRASH_CHROMIUM)\n");
        TEST_END();
    }
    snprintf(tdir, sizeof tdir, "/tmp/mcrash_page_XXXXXX");
    if (!mkdtemp(tdir)) return 1;
    RUN(test_checks_fail_on_bad_pages);
    RUN(test_report_in_chromium);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tdir);
    TEST_END();
}
