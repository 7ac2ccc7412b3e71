/* cli.h: the `mcrash` subcommands (DESIGN.md "The command"). One file per subcommand,
 * cli/cmd_<name>.c defining `int cli_<name>(int argc, char **argv)`; argv[0] is the
 * subcommand name. Return the exit status: 0 done, 1 simulation failed, 2 bad input/usage. */
#ifndef MCS_CLI_H
#define MCS_CLI_H

/* X(name, usage, summary) */
#define MCS_CLI_COMMANDS(X)                                                                        \
    X(check, "mcrash check SCENARIO.yaml... | --json SCENARIO.yaml | --schema",                    \
      "validate scenarios; --json prints one resolved (includes merged, SI); --schema the keys")  \
    X(run, "mcrash run SCENARIO.yaml [-o OUT.h5] [--stage 1|2|3|all] [--motion STAGE1.h5] "        \
           "[--quiet] [--json]",                                                                   \
      "run a scenario through its stages")                                                         \
    X(stage1, "mcrash stage1 SCENARIO.yaml [-o OUT.h5] [--quiet] [--json]",                        \
      "run the multibody model (ODE)")                                                             \
    X(stage2, "mcrash stage2 SCENARIO.yaml [-o OUT.h5] [--motion STAGE1.h5] [--quiet] [--json]",   \
      "run the FE rider-interaction model on stage-1 vehicle motion")                              \
    X(stage3, "mcrash stage3 SCENARIO.yaml [-o OUT.h5] [--quiet] [--json]",                        \
      "run the full FE vehicle model")                                                             \
    X(rom, "mcrash rom SCENARIO.yaml [-o OUT.h5] [--append] [--quiet] [--json]",                   \
      "run the reduced-order lumped-mass model (CVODE) into /stage0")                              \
    X(retune, "mcrash retune STAGE3.h5 --scenario STAGE1.yaml [-o CURVES.yaml] [--end-time T] "    \
              "[-j N] [--csv FILE] [--svg PREFIX] [--json]",                                       \
      "fit stage-1 front characteristics to stage-3 wall force and fork angle")                    \
    X(loop, "mcrash loop SCENARIO.yaml [--max-iter N] [-o DIR] [-j N]",                            \
      "stage 3 -> retune -> stage 1 -> stage 2 until the ratings settle")                          \
    X(injury, "mcrash injury OUT.h5 [B.h5 ...] [--stage N] [--dummy SIZE] [--json]",               \
      "injury criteria of results files (one column per file)")                                   \
    X(energy, "mcrash energy OUT.h5 [--stage N] [--group NAME] [--json]",                          \
      "the rider's energy balance and its transfer to each contact partner, ranked")              \
    X(signal, "mcrash signal hic|a3ms|cfc|nij|bric|vc|ti FILE.csv [--class CFC] [--window S] [--json]", \
      "filter a channel or compute one criterion from CSV")                                        \
    X(compare, "mcrash compare REF CMP | OUT.h5 --stages A,B [--method iso18571|cora] [--json]",   \
      "objective rating of one curve against another")                                             \
    X(export, "mcrash export OUT.h5 --xdmf [FILE.xmf] [--stride N] | --xdmf2 [FILE.xmf] | "         \
              "--csv DIR | --mme DIR [--stage N] | --k FILE [--stage N] [--deformed] [--units mm-s-t] [--long|--i10]",                                                  \
      "write a results file in other formats (XDMF for ParaView, CSV, LS-DYNA keyword mesh)")                            \
    X(report, "mcrash report OUT.h5 [-o DIR]",                                                 \
      "one self-contained HTML page of a results file (plots, injury bars, snapshots)")        \
    X(study, "mcrash study STUDY.yaml [-o STUDY.h5] [-j N] [--quiet] | --analyze STUDY.h5 [--json]", \
      "design of experiments: run its cases, or analyse the study file")

#define MCS_CLI_DECL(name, usage, summary) int cli_##name(int argc, char **argv);
MCS_CLI_COMMANDS(MCS_CLI_DECL)
#undef MCS_CLI_DECL

/* print "mcrash NAME: not built yet (see issue N)" and return 2 */
int cli_not_built(const char *name, const char *where);

/* print the usage line of a subcommand on stderr and return 2 */
int cli_usage(const char *name);

/* true if s is "-h" or "--help"; then the usage is printed on stdout */
int cli_wants_help(const char *name, int argc, char **argv);

#endif
