#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep bench [--workload NAME]... [--growth] [--threshold] [--epsilon [--json FILE]]
/// [--threads N] [--embree-isa ISA] [--quick]` or
/// `raystep bench --pareto [--cases PATH]... [--out FOLDER] [--quick]` or
/// `raystep bench --sampling [--json FILE] [--quick]`
struct BenchArguments {
    std::vector<std::string> workloads;  ///< scenes or workloads; none: every one
    bool growth = false;                 ///< the growth table
    bool threshold = false;              ///< where a BVH starts to pay
    bool epsilon = false;                ///< the epsilon study of stage 6
    std::string json;     ///< where the epsilon or sampling study's figures go; empty: nowhere
    bool pareto = false;  ///< the speed-against-error study, alone
    std::vector<std::string> cases;  ///< its case files or folders; none: stage 3's own
    std::string out;                 ///< the folder its pareto.json goes into
    int threads = 0;                 ///< the all-threads columns' threads; 0: every hardware thread
    std::string embree_isa;          ///< the instruction set Embree is held to; empty: its best
    bool scale = false;              ///< the scale bars on scenes/scale/
    bool sampling = false;           ///< the sampling noise study of stage 8, alone
    bool quick = false;              ///< an eighth of the rays, for smoke tests
};

/// Adds the `bench` subcommand to `app`; parsing fills `arguments`. An unknown workload or a
/// thread count out of range is a command-line error (exit 2).
CLI::App* add_bench_command(CLI::App& app, BenchArguments& arguments);

/// Measures our acceleration structures, and any registered baseline (Embree in
/// raystep-reference), and prints a table per workload: docs/stage4.md, "raystep bench"; with
/// --epsilon, the acne and leaks of each ray offset rule on the acne scenes: docs/stage6.md,
/// "Measuring acne"; with --pareto, only the speed-against-error study of docs/stage3.md, which
/// raystep-reference alone links (pareto_registry.h); with --sampling, only the noise study of
/// docs/measurements/sampling-noise.md (studies/sampling/noise_command.h), exit code 1 when one
/// of its findings does not hold; --json without --epsilon or --sampling exits 2. Without
/// --workload, --growth, --threshold or
/// --epsilon, runs them all. A structure that is a stub or fails gets its reason in its row and the
/// others go on. Exit code 0; 1 when a cross-check found two structures that return different hits.
int run_bench(const BenchArguments& arguments);

}  // namespace raystep
