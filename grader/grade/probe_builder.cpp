#include "grader/grade/probe_builder.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "grader/sandbox/sandbox.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

// The compiler's or linker's output as a report shows it: enough to see the first error.
constexpr std::size_t kFirstLines = 25;

std::string first_lines(const std::string& text) {
    std::istringstream in(text);
    std::string kept;
    std::size_t count = 0;
    for (std::string line; std::getline(in, line) && count < kFirstLines; ++count) {
        kept += line + "\n";
    }
    return kept;
}

// The headers a submission compiles against: the contracts, never the solutions or the grader.
void copy_headers(const fs::path& source, const fs::path& include) {
    for (const char* folder : {"core", "stages"}) {
        for (const auto& entry : fs::recursive_directory_iterator(source / folder)) {
            if (!entry.is_regular_file() || entry.path().extension() != ".h") continue;
            const fs::path target = include / fs::relative(entry.path(), source);
            fs::create_directories(target.parent_path());
            fs::copy_file(entry.path(), target, fs::copy_options::overwrite_existing);
        }
    }
}

// Compiler limits: a template bomb or a huge constant array must end, not stall the grading.
SandboxPolicy compile_policy(const fs::path& include, const fs::path& sources,
                             const fs::path& objects) {
    SandboxPolicy policy;
    policy.read_only = {include, sources};
    policy.writable = objects;
    policy.working_directory = objects;
    policy.limits.cpu_seconds = 60;
    policy.limits.wall = std::chrono::seconds(120);
    policy.limits.address_space_bytes = std::size_t{3} << 30;
    policy.limits.file_size_bytes = 256u << 20;
    policy.limits.output_bytes = 64u << 10;
    return policy;
}

struct CompiledStage {
    int number = 0;
    std::vector<fs::path> objects;
    std::string failure;
};

CompiledStage compile_stage(const SubmittedStage& stage, const ProbeToolchain& toolchain,
                            const fs::path& include, const fs::path& work) {
    CompiledStage compiled;
    compiled.number = stage.manifest.number;
    if (!stage.missing.empty()) {
        compiled.failure = "missing from the submission:";
        for (const std::string& file : stage.missing) {
            compiled.failure += " stages/" + stage.manifest.folder + "/" + file;
        }
        return compiled;
    }
    const fs::path objects = work / "objects" / stage.manifest.folder;
    fs::create_directories(objects);
    for (const fs::path& file : stage.files) {
        const fs::path object = objects / file.filename().replace_extension(".o");
        std::vector<std::string> argv = {toolchain.compiler.string()};
        argv.insert(argv.end(), toolchain.compile_flags.begin(), toolchain.compile_flags.end());
        argv.insert(argv.end(), {"-I" + include.string(), "-c", file.string(), "-o", object.string()});
        const SandboxRun run =
            run_sandboxed(argv, "", compile_policy(include, file.parent_path(), objects));
        if (run.exit_code != 0 || run.timed_out) {
            compiled.failure = (run.timed_out ? "the compiler ran out of time on " : "") +
                               first_lines(run.errors + run.output);
            if (compiled.failure.empty()) compiled.failure = "the compiler failed without a message";
            return compiled;
        }
        compiled.objects.push_back(object);
    }
    return compiled;
}

BuiltProbe link_probe(const std::vector<const CompiledStage*>& submitted,
                      const ProbeToolchain& toolchain, const fs::path& program) {
    std::vector<std::string> argv = {toolchain.compiler.string(), "-o", program.string()};
    std::vector<int> from_submission;
    for (const fs::path& object : toolchain.probe_objects) argv.push_back(object.string());
    for (const CompiledStage* stage : submitted) {
        from_submission.push_back(stage->number);
        for (const fs::path& object : stage->objects) argv.push_back(object.string());
    }
    // Higher stages call lower ones: a one-pass linker needs them in that order.
    for (auto it = toolchain.stage_libraries.rbegin(); it != toolchain.stage_libraries.rend(); ++it) {
        if (std::find(from_submission.begin(), from_submission.end(), it->first) ==
            from_submission.end()) {
            argv.push_back(it->second.string());
        }
    }
    for (const fs::path& library : toolchain.libraries) argv.push_back(library.string());
    argv.insert(argv.end(), toolchain.link_flags.begin(), toolchain.link_flags.end());

    SandboxPolicy policy;
    for (const fs::path& input : toolchain.probe_objects) policy.read_only.push_back(input.parent_path());
    for (const auto& [number, library] : toolchain.stage_libraries) policy.read_only.push_back(library.parent_path());
    for (const fs::path& library : toolchain.libraries) policy.read_only.push_back(library.parent_path());
    for (const CompiledStage* stage : submitted) {
        if (!stage->objects.empty()) policy.read_only.push_back(stage->objects.front().parent_path());
    }
    std::sort(policy.read_only.begin(), policy.read_only.end());
    policy.read_only.erase(std::unique(policy.read_only.begin(), policy.read_only.end()),
                           policy.read_only.end());
    policy.writable = program.parent_path();
    policy.working_directory = program.parent_path();
    policy.limits.cpu_seconds = 60;
    policy.limits.wall = std::chrono::seconds(120);
    policy.limits.file_size_bytes = 512u << 20;
    policy.limits.output_bytes = 64u << 10;
    const SandboxRun run = run_sandboxed(argv, "", policy);
    if (run.exit_code != 0 || run.timed_out) {
        return {std::nullopt, "the link failed: " + first_lines(run.errors + run.output)};
    }
    return {program, ""};
}

}  // namespace

const BuiltProbe& ProbeSet::stage(int number) const {
    for (const auto& [n, probe] : stages) {
        if (n == number) return probe;
    }
    throw std::out_of_range("no probe for stage " + std::to_string(number));
}

ProbeSet build_probes(const Submission& submission, const ProbeToolchain& toolchain,
                      const fs::path& work, int jobs) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path include = work / "include";
    copy_headers(toolchain.source, include);
    fs::create_directories(work / "probes");

    // Compile the stages `jobs` at a time: each is independent of the others.
    std::vector<CompiledStage> compiled(submission.stages.size());
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> workers;
    for (int k = 0; k < std::max(1, jobs); ++k) {
        workers.emplace_back([&] {
            for (std::size_t s = next++; s < compiled.size(); s = next++) {
                compiled[s] = compile_stage(submission.stages[s], toolchain, include, work);
            }
        });
    }
    for (std::thread& worker : workers) worker.join();

    ProbeSet set;
    std::vector<const CompiledStage*> all;
    std::string pipeline_failure;
    for (const CompiledStage& stage : compiled) {
        const fs::path program = work / "probes" / ("stage" + std::to_string(stage.number));
        if (!stage.failure.empty()) {
            set.stages.push_back({stage.number, {std::nullopt, stage.failure}});
            pipeline_failure += "stage " + std::to_string(stage.number) + " did not compile. ";
        } else {
            set.stages.push_back({stage.number, link_probe({&stage}, toolchain, program)});
        }
        all.push_back(&stage);
    }
    if (pipeline_failure.empty()) {
        set.pipeline = link_probe(all, toolchain, work / "probes" / "pipeline");
    } else {
        set.pipeline.failure = pipeline_failure;
    }
    set.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return set;
}

}  // namespace raystep::grade
