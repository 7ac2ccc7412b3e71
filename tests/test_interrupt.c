/* test_interrupt.c: how a run ends other than at its end time (issue 18 item 4,
 * core/mcs_interrupt.h, docs/reliability.md "Interrupts and failures"). bin/mcrash is started
 * on a run far longer than the test, and signalled once its results temporary exists and it has
 * run a while:
 *   - SIGINT (and SIGTERM) during `mcrash stage1` / `run` / `stage3`: exit 130, the results file
 *     readable, /meta status = "interrupted", its last time before the end time, no temporary;
 *   - SIGINT then SIGTERM at once (two signals; two SIGINTs sent together may merge into one):
 *     exit 130, no results file and no temporary;
 *   - a numerical failure (stage 1 and stage 3): exit 1, no results file, and the failure record
 *     OUT.h5.failure.txt with the time, the body or element and the energies.
 * The reference of each check is the contract in core/mcs_interrupt.h, not the code's output. */
#include "core/mcs_results.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <time.h>

static char tmpdir[64];

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

static int file_exists(const char *p) { return access(p, F_OK) == 0; }

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void sleep_s(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&ts, NULL);
}

/* files in tmpdir whose name contains `part` */
static int count_matching(const char *part)
{
    DIR *d = opendir(tmpdir);
    int n = 0;
    if (!d) return -1;
    for (struct dirent *e; (e = readdir(d));)
        if (strstr(e->d_name, part)) n++;
    closedir(d);
    return n;
}

/* start `mcrash args[0..]` (stdout, stderr to tmpdir/log); returns the pid */
static pid_t spawn(char *const *args)
{
    pid_t pid = fork();
    if (pid == 0) {
        char log[128];
        snprintf(log, sizeof log, "%s/log", tmpdir);
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
        execv(cli_bin(), args);
        _exit(127);
    }
    return pid;
}

/* wait until the run's temporary OUT.tmp.<pid> exists (it is opened before the time loop),
 * then `extra` seconds more; 0 when it never appeared in 120 s or the process ended */
static int wait_started(pid_t pid, const char *out, double extra)
{
    char tmp[256];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", out, (long)pid);
    double t0 = now_s();
    while (!file_exists(tmp)) {
        if (now_s() - t0 > 120 || waitpid(pid, NULL, WNOHANG) == pid) return 0;
        sleep_s(0.01);
    }
    sleep_s(extra);
    return 1;
}

/* exit status of pid (128 + signal when killed); it is killed after 120 s */
static int wait_exit(pid_t pid)
{
    int st = 0;
    double t0 = now_s();
    while (waitpid(pid, &st, WNOHANG) == 0) {
        if (now_s() - t0 > 120) kill(pid, SIGKILL);
        sleep_s(0.01);
    }
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

/* the results file out: status "interrupted" and its last `time` sample in (0, t_end) */
static void check_interrupted_file(const char *out, const char *time_path, double t_end)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    if (!r) return;
    char *status = NULL;
    CHECK(mcs_results_attr_str(r, "/meta", "status", &status, &e) == MCS_OK);
    CHECK(status && strcmp(status, "interrupted") == 0);
    free(status);
    mcs_array t = {0};
    CHECK(mcs_results_read(r, time_path, &t, &e) == MCS_OK);
    double last = t.n ? t.v[t.n - 1] : -1;
    printf("interrupt | %s | %zu samples | last %.6g s | end %.6g s\n", time_path, t.n, last,
           t_end);
    CHECK(t.n >= 1);
    CHECK(last >= 0 && last < t_end);
    mcs_array_free(&t);
    mcs_results_close(&r);
}

/* a body coasting in free space for 1000 s at 1 ms steps: hours of run, stopped by the test */
static const char *const long_s1 =
    "mcrash: 1\nname: coast\nsimulation: {end_time: 1000 s, time_step: 1 ms, output_rate: 100}\n"
    "environment: {gravity: 0}\n"
    "bodies:\n"
    "  - {name: puck, mass: 1 kg, inertia: [1, 1, 1], position: [0, 0, 1], velocity: [1, 0, 0]}\n";

/* a steel block coasting for 10 s at microsecond steps */
static const char *const long_s3 =
    "mcrash: 1\nname: coast3\nsimulation: {end_time: 10 s, output_rate: 1 kHz}\nfe:\n  parts:\n"
    "    - name: block\n"
    "      mesh: {generate: box, size: [10 mm, 10 mm, 10 mm], divisions: [2, 2, 2]}\n"
    "      section: {type: solid}\n"
    "      material: {model: elastic, density: 8000 kg/m^3, youngs_modulus: 200 GPa,"
    " poisson: 0.3}\n"
    "      initial_velocity: [1 m/s, 0, 0]\n";

static void interrupt_case(const char *cmd, const char *scn_text, int sig, const char *time_path,
                           double t_end)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/long.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/long.h5", tmpdir);
    write_text(scn, scn_text);
    remove(out);
    char *args[] = {(char *)cli_bin(), (char *)cmd, scn, "-o", out, "--quiet", NULL};
    pid_t pid = spawn(args);
    CHECK(pid > 0);
    CHECK(wait_started(pid, out, 0.3));
    double t0 = now_s();
    kill(pid, sig);
    int rc = wait_exit(pid);
    printf("interrupt | %s | signal %d | exit %d | %.3f s from the signal to the exit\n", cmd, sig,
           rc, now_s() - t0);
    CHECK(rc == 130);
    CHECK(file_exists(out));
    CHECK(count_matching(".tmp.") == 0);
    if (file_exists(out)) check_interrupted_file(out, time_path, t_end);
    char log[128], text[4096];
    snprintf(log, sizeof log, "%s/log", tmpdir);
    cli_slurp(log, text, sizeof text);
    CHECK_STR_CONTAINS(text, "interrupted at t = ");
    remove(out);
}

static void test_sigint_stage1(void)
{
    interrupt_case("stage1", long_s1, SIGINT, "/stage1/time", 1000);
}

static void test_sigterm_run(void)
{
    interrupt_case("run", long_s1, SIGTERM, "/stage1/time", 1000);
}

static void test_sigint_stage3(void)
{
    interrupt_case("stage3", long_s3, SIGINT, "/stage3/time", 10);
}

/* two signals: stopped at once, nothing left */
static void test_second_signal_leaves_no_file(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/long.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/twice.h5", tmpdir);
    write_text(scn, long_s1);
    char *args[] = {(char *)cli_bin(), "stage1", scn, "-o", out, "--quiet", NULL};
    pid_t pid = spawn(args);
    CHECK(wait_started(pid, out, 0.3));
    kill(pid, SIGINT);
    kill(pid, SIGTERM);
    int rc = wait_exit(pid);
    printf("interrupt | two signals | exit %d\n", rc);
    CHECK(rc == 130);
    CHECK(!file_exists(out));
    CHECK(count_matching("twice") == 0); /* neither the file nor its temporary */
    char log[128], text[4096];
    snprintf(log, sizeof log, "%s/log", tmpdir);
    cli_slurp(log, text, sizeof text);
    CHECK_STR_CONTAINS(text, "second signal");
}

/* the record's text: its keys (core/mcs_interrupt.h) and the place */
static void check_record(const char *out, const char *stage, const char *where,
                         const char *energy)
{
    char rec[256], text[4096];
    snprintf(rec, sizeof rec, "%s.failure.txt", out);
    CHECK(file_exists(rec));
    cli_slurp(rec, text, sizeof text);
    printf("failure record | %s\n%s", out, text);
    CHECK_STR_CONTAINS(text, "mcrash failure record\n");
    CHECK_STR_CONTAINS(text, stage);
    CHECK_STR_CONTAINS(text, "\ntime_s: ");
    CHECK_STR_CONTAINS(text, "\nstep: ");
    CHECK_STR_CONTAINS(text, where);
    CHECK_STR_CONTAINS(text, "\nmessage: ");
    CHECK_STR_CONTAINS(text, energy);
    remove(rec);
}

static void test_numerical_failure_record_stage1(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/unstable.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/unstable.h5", tmpdir);
    /* a 1 kg ball on a contact of k = 1e6 N / 1 mm = 1e9 N/m at 100 us steps: the step is past
     * the contact's stable limit 2 sqrt(m/k) = 63 us and the energy grows (the case of
     * test_mb_run_cli.c) */
    write_text(scn, "mcrash: 1\n"
                    "simulation: {end_time: 0.1 s, time_step: 100 us}\n"
                    "environment: {gravity: 9.81, ground: {height: 0}}\n"
                    "characteristics: {stiff: {loading: [[0, 0], [0.001, 1e6]]}}\n"
                    "bodies:\n"
                    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004],"
                    " position: [0, 0, 0.1005],\n"
                    "     velocity: [0, 0, -1],\n"
                    "     surfaces: [{type: ellipsoid, center: [0, 0, 0],"
                    " semi_axes: [0.1, 0.1, 0.1]}]}\n"
                    "contacts: [{a: ball, b: ground, characteristic: stiff}]\n");
    snprintf(args, sizeof args, "stage1 %s -o %s --quiet", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 1);
    CHECK(!file_exists(out));
    CHECK(count_matching(".tmp.") == 0);
    check_record(out, "\nstage: 1\n", "\nwhere: body ball\n", "\nenergy_total_J: ");
}

static void test_numerical_failure_record_stage3(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/smash.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/smash.h5", tmpdir);
    /* a very soft block thrown at 2 km/s: its first element turns inside out (test_s3_run.c) */
    write_text(scn, "mcrash: 1\nname: smash\nsimulation: {end_time: 100 us}\nfe:\n  parts:\n"
                    "    - name: bar\n"
                    "      mesh: {generate: box, size: [10 mm, 10 mm, 10 mm],"
                    " divisions: [4, 1, 1]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000 kg/m^3,"
                    " youngs_modulus: 1 MPa, poisson: 0.3}\n"
                    "      initial_velocity: [-2000 m/s, 0, 0]\n"
                    "  rigid_walls: [{name: wall, point: [-1 um, 0, 0], normal: [1, 0, 0]}]\n");
    snprintf(args, sizeof args, "stage3 %s -o %s --quiet", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 1);
    CHECK(!file_exists(out));
    check_record(out, "\nstage: 3\n", "\nwhere: part 'bar' element ", "\nenergy_kinetic_J: ");
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_intr_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_sigint_stage1);
    RUN(test_sigterm_run);
    RUN(test_sigint_stage3);
    RUN(test_second_signal_leaves_no_file);
    RUN(test_numerical_failure_record_stage1);
    RUN(test_numerical_failure_record_stage3);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) fprintf(stderr, "cannot remove %s\n", tmpdir);
    TEST_END();
}
