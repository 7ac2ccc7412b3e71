/* cli_common.c: argument parsing, scenario loading and JSON strings shared by subcommands */
#include "cli/cli_common.h"
#include "cli/cli.h"

#include <stdio.h>
#include <string.h>

int cli_parse_run_args(int argc, char **argv, int with_stage, cli_run_args *a)
{
    memset(a, 0, sizeof *a);
    a->stage = "all";
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--json") == 0)
            a->json = 1;
        else if (strcmp(s, "--quiet") == 0)
            a->quiet = 1;
        else if (strcmp(s, "-o") == 0 && i + 1 < argc)
            a->out = argv[++i];
        else if (with_stage && strcmp(s, "--stage") == 0 && i + 1 < argc)
            a->stage = argv[++i];
        else if ((with_stage || strcmp(argv[0], "stage2") == 0) && strcmp(s, "--motion") == 0 &&
                 i + 1 < argc)
            a->motion = argv[++i];
        else if (s[0] == '-' && s[1]) {
            fprintf(stderr, "mcrash %s: unknown option '%s'\n", argv[0], s);
            return cli_usage(argv[0]);
        } else if (a->path)
            return cli_usage(argv[0]);
        else
            a->path = s;
    }
    if (!a->path) return cli_usage(argv[0]);
    if (strcmp(a->stage, "1") && strcmp(a->stage, "2") && strcmp(a->stage, "3") &&
        strcmp(a->stage, "all")) {
        fprintf(stderr, "mcrash %s: --stage takes 1, 2, 3 or all (got '%s')\n", argv[0], a->stage);
        return 2;
    }
    if (!a->out) {
        cli_default_output(a->path, a->def_out, sizeof a->def_out);
        a->out = a->def_out;
    }
    return -1;
}

mcs_scenario *cli_load_scenario(const char *path, int *rc)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mcs_status st = mcs_scenario_load(path, &scn, &err);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        *rc = mcs_status_exit_code(st);
        return NULL;
    }
    return scn;
}

void cli_default_output(const char *scenario, char *out, size_t n)
{
    const char *base = strrchr(scenario, '/');
    base = base ? base + 1 : scenario;
    size_t len = strlen(base);
    const char *ext[] = {".yaml", ".yml"};
    for (int i = 0; i < 2; i++) {
        size_t k = strlen(ext[i]);
        if (len > k && strcmp(base + len - k, ext[i]) == 0) {
            len -= k;
            break;
        }
    }
    snprintf(out, n, "%.*s.h5", (int)len, base);
}

void cli_json_string(const char *s)
{
    putchar('"');
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            printf("\\%c", *p);
        else if (*p < 0x20)
            printf("\\u%04x", *p);
        else
            putchar(*p);
    }
    putchar('"');
}
