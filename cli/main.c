/* main.c: `mcrash` — dispatch to the subcommands of cli.h */
#include "cli/cli.h"
#include "core/mcs_interrupt.h"
#include "core/mcs_version.h"
#include "stage3_fe/s3_moto.h"
#include "stage3_fe/s3_sedan.h"

#include <stdio.h>
#include <string.h>

typedef struct {
    const char *name, *usage, *summary;
    int (*fn)(int, char **);
} cli_command;

static const cli_command commands[] = {
#define MCS_CLI_ROW(name, usage, summary) {#name, usage, summary, cli_##name},
    MCS_CLI_COMMANDS(MCS_CLI_ROW)
#undef MCS_CLI_ROW
};
static const int ncommands = (int)(sizeof commands / sizeof commands[0]);

static const cli_command *find(const char *name)
{
    for (int i = 0; i < ncommands; i++)
        if (strcmp(commands[i].name, name) == 0) return &commands[i];
    return NULL;
}

static void print_help(FILE *f)
{
    fprintf(f, "mcrash %s: motorcycle crash simulation in three stages\n\n"
               "usage: mcrash SUBCOMMAND [ARGS]\n\n",
            MCS_VERSION);
    for (int i = 0; i < ncommands; i++)
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\n  mcrash help SUBCOMMAND   usage of one subcommand\n"
               "  mcrash --version\n\n"
               "exit status: 0 done, 1 the simulation failed, 2 bad input or usage\n");
}

int cli_usage(const char *name)
{
    const cli_command *c = find(name);
    if (c) fprintf(stderr, "usage: %s\n", c->usage);
    return 2;
}

int cli_wants_help(const char *name, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            const cli_command *c = find(name);
            if (c) printf("usage: %s\n  %s\n", c->usage, c->summary);
            return 1;
        }
    }
    return 0;
}

int cli_not_built(const char *name, const char *where)
{
    fprintf(stderr, "mcrash %s: not built yet (%s)\n", name, where);
    return 2;
}

int main(int argc, char **argv)
{
    s3_moto_register(); /* fe.parts mesh generate: motorcycle */
    s3_sedan_register(); /* fe.parts mesh generate: sedan_side */
    if (argc < 2) {
        print_help(stderr);
        return 2;
    }
    const char *sub = argv[1];
    if (strcmp(sub, "--help") == 0 || strcmp(sub, "-h") == 0) {
        print_help(stdout);
        return 0;
    }
    if (strcmp(sub, "--version") == 0 || strcmp(sub, "version") == 0) {
        printf("mcrash %s\n", MCS_VERSION);
        return 0;
    }
    if (strcmp(sub, "help") == 0) {
        if (argc < 3) {
            print_help(stdout);
            return 0;
        }
        const cli_command *c = find(argv[2]);
        if (!c) {
            fprintf(stderr, "mcrash: unknown subcommand '%s'\n", argv[2]);
            return 2;
        }
        printf("usage: %s\n  %s\n", c->usage, c->summary);
        return 0;
    }
    const cli_command *c = find(sub);
    if (!c) {
        fprintf(stderr, "mcrash: unknown subcommand '%s' (mcrash --help lists them)\n", sub);
        return 2;
    }
    /* the runs stop cleanly on SIGINT / SIGTERM: results up to then, exit 130; a second
     * signal stops at once without a file (core/mcs_interrupt.h) */
    static const char *const runs[] = {"run", "stage1", "stage2", "stage3"};
    for (int i = 0; i < 4; i++)
        if (strcmp(sub, runs[i]) == 0) mcs_interrupt_install();
    return c->fn(argc - 1, argv + 1);
}
