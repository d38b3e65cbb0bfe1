#include "grader/grade/probe_builder.h"

#include <cxxabi.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "grader/grade/mebibytes.h"
#include "grader/grade/object_cache.h"
#include "grader/grade/sandbox_copies.h"
#include "grader/sandbox/sandbox.h"
#include "grader/sandbox/sandbox_paths.h"
#include "grader/sandbox/sandbox_user.h"

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

// The compiler's messages with the work folder's paths made the repository's: a student reads
// "stages/1_vectors/vectors.cpp:85:12: error: ...", as their own build would say it, not where
// the grader happened to compile it.
std::string with_repository_paths(std::string text, const fs::path& work) {
    for (const fs::path& folder : {work / "submission", work / "include", work}) {
        const std::string prefix = folder.string() + "/";
        for (std::size_t at = text.find(prefix); at != std::string::npos;
             at = text.find(prefix, at))
            text.erase(at, prefix.size());
    }
    return text;
}

// The headers a submission compiles against: the stages' contracts and what they build on (base/),
// never the solutions, the studies or the grader.
void copy_headers(const fs::path& source, const fs::path& include) {
    for (const char* folder : {"base", "stages"}) {
        for (const auto& entry : fs::recursive_directory_iterator(source / folder)) {
            if (!entry.is_regular_file() || entry.path().extension() != ".h") continue;
            const fs::path target = include / fs::relative(entry.path(), source);
            fs::create_directories(target.parent_path());
            copy_file_for_sandbox(entry.path(), target, kSharedFile);
        }
    }
}

// The precompiled header (probe_precompiled.h) where the sandbox's user can read it: linked into
// `folder` from the build tree when anyone may read the build's file and both lie on one file
// system, else copied (some 50 MB). The header's path there, for -include; empty where the build
// made none, and a compile then parses everything itself.
fs::path place_precompiled_header(const ProbeToolchain& toolchain, const fs::path& folder) {
    const fs::path& header = toolchain.precompiled_header;
    const fs::path compiled = header.string() + ".gch";
    if (header.empty() || !fs::is_regular_file(header) || !fs::is_regular_file(compiled)) return {};
    fs::create_directories(folder);
    for (const fs::path& from : {header, compiled}) {
        const fs::path to = folder / from.filename();
        const bool readable =
            (fs::status(from).permissions() & fs::perms::others_read) != fs::perms::none;
        std::error_code not_linked;
        if (readable) fs::create_hard_link(from, to, not_linked);
        if (!readable || not_linked) copy_file_for_sandbox(from, to, kSharedFile);
    }
    return folder / header.filename();
}

// What a probe's link reads, copied into work/link: the parts every probe shares in common/, and
// each reference stage in stageN/, so that a link is shown only the stages it takes from the
// reference. System libraries stay where they are: the sandbox shows /usr.
struct StagedToolchain {
    fs::path common;
    std::vector<std::string> objects;    ///< the probe's calls, the renderer, app/check
    std::vector<std::string> libraries;  ///< below the stages, in link order
    /// Of those, what a stage's code may call: base/ (raystep_base, raystep_scene) and the system's
    /// (ARCHITECTURE.md, "Layers"); not the protocol with its case files, nor the views.
    std::vector<std::string> base_libraries;
    std::map<int, fs::path> stage_libraries;
};

// The libraries a stage's code may call, of those the probe links: base/'s and the system's.
bool below_the_stages(const fs::path& library) {
    const std::string name = library.filename().string();
    return name == "libraystep_base.a" || name == "libraystep_scene.a" ||
           name.rfind("libraystep_", 0) != 0;
}

StagedToolchain stage_toolchain(const ProbeToolchain& toolchain, const fs::path& link) {
    StagedToolchain staged;
    staged.common = link / "common";
    fs::create_directories(staged.common);
    std::size_t index = 0;
    const auto copy_common = [&](const fs::path& file) {
        // Numbered, so that two inputs of the same name (view.cpp.o of two libraries) never meet.
        const fs::path target =
            staged.common / (std::to_string(index++) + "-" + file.filename().string());
        copy_file_for_sandbox(file, target, kSharedFile);
        return target.string();
    };
    for (const fs::path& object : toolchain.probe_objects)
        staged.objects.push_back(copy_common(object));
    for (const fs::path& library : toolchain.libraries) {
        staged.libraries.push_back(is_within(library, "/usr") ? library.string()
                                                              : copy_common(library));
        if (below_the_stages(library)) staged.base_libraries.push_back(staged.libraries.back());
    }
    for (const auto& [number, library] : toolchain.stage_libraries) {
        const fs::path folder = link / ("stage" + std::to_string(number));
        fs::create_directories(folder);
        staged.stage_libraries[number] = folder / library.filename();
        copy_file_for_sandbox(library, staged.stage_libraries[number], kSharedFile);
    }
    return staged;
}

// Runs task(0) to task(count - 1), `jobs` at a time: the compiles and links of one submission are
// independent of one another. The first exception a task throws is thrown here, once all have
// ended.
template <class Task>
void run_at_a_time(std::size_t count, int jobs, const Task& task) {
    std::atomic<std::size_t> next{0};
    std::mutex mutex;
    std::exception_ptr first_error;
    std::vector<std::thread> workers;
    for (int k = 0; k < std::max(1, jobs); ++k) {
        workers.emplace_back([&] {
            for (std::size_t i = next++; i < count; i = next++) {
                try {
                    task(i);
                } catch (...) {
                    const std::lock_guard<std::mutex> lock(mutex);
                    if (!first_error) first_error = std::current_exception();
                }
            }
        });
    }
    for (std::thread& worker : workers)
        worker.join();
    if (first_error) std::rethrow_exception(first_error);
}

struct CompiledStage {
    int number = 0;
    std::vector<fs::path> objects;
    std::string failure;
};

// A folder's files' sizes, added up.
std::uintmax_t bytes_in(const fs::path& folder) {
    std::uintmax_t total = 0;
    std::error_code error;
    for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error)) {
        if (it->is_regular_file(error)) total += it->file_size(error);
    }
    return total;
}

// Whether a failed compile or link ran into its file-size budget. The driver (g++) reports a
// pass killed by SIGXFSZ in words and exits with an error of its own; the output left behind
// tells too.
bool passed_file_budget(const SandboxRun& run, std::uintmax_t written, std::uintmax_t budget) {
    return run.signal == SIGXFSZ ||
           run.errors.find("File size limit exceeded") != std::string::npos || written >= budget;
}

// The sandbox must show its user the work folder, or every compile would fail as if the student's
// code had: a mistake of the grader's setting (a work folder under a folder nobody may enter, a
// bubblewrap that cannot bind it) stops the grade instead, with bubblewrap's or the kernel's words.
void require_sandbox_reaches(const fs::path& include, const fs::path& work) {
    SandboxPolicy policy;
    policy.read_only = {include};
    policy.working_directory = include;
    const SandboxRun run = run_sandboxed({"test", "-r", (include / "base").string()}, "", policy);
    if (run.exit_code != 0) {
        throw std::runtime_error(
            "the sandbox cannot show its user the work folder " + work.string() + ": " +
            (run.errors.empty() ? "the headers there cannot be read" : run.errors.substr(0, 400)));
    }
}

// Compiles a stage's files one after another, each under what is left of the stage's budget: a
// template bomb or a huge constant array ends, and so does a stage split into many slow files.
CompiledStage compile_stage(const SubmittedStage& stage, const ProbeToolchain& toolchain,
                            const fs::path& include, const fs::path& precompiled,
                            const fs::path& work, const ObjectCache* cache,
                            const BuildBudget& budget) {
    CompiledStage compiled;
    compiled.number = stage.manifest.number;
    if (!stage.missing.empty()) {
        compiled.failure = "missing from the submission:";
        for (const std::string& file : stage.missing) {
            compiled.failure += " stages/" + stage.manifest.folder + "/" + file;
        }
        for (const std::string& note : stage.notes)
            compiled.failure += "\n" + note;
        return compiled;
    }
    const fs::path objects = work / "objects" / stage.manifest.folder;
    fs::create_directories(objects);
    double seconds_left = budget.compile_seconds_per_stage;
    for (const fs::path& file : stage.files) {
        const std::uintmax_t written = bytes_in(objects);
        if (seconds_left < 1.0 || written >= budget.compile_bytes_per_stage) {
            compiled.failure = "the stage's budget ran out before " + file.filename().string();
            return compiled;
        }
        const fs::path object = objects / file.filename().replace_extension(".o");
        if (cache && cache->take(file, object)) {
            compiled.objects.push_back(object);
            continue;
        }
        std::vector<std::string> argv = {toolchain.compiler.string()};
        argv.insert(argv.end(), toolchain.compile_flags.begin(), toolchain.compile_flags.end());
        if (!precompiled.empty()) argv.insert(argv.end(), {"-include", precompiled.string()});
        argv.insert(argv.end(),
                    {"-I" + include.string(), "-c", file.string(), "-o", object.string()});
        if (cache) {
            for (const std::string& flag : ObjectCache::dependency_flags(object))
                argv.push_back(flag);
        }

        SandboxPolicy policy;
        policy.read_only = {include, file.parent_path()};
        if (!precompiled.empty()) policy.read_only.push_back(precompiled.parent_path());
        policy.writable = objects;
        policy.working_directory = objects;
        policy.limits.cpu_seconds = seconds_left;
        policy.limits.wall = std::chrono::milliseconds(static_cast<long>(1000 * seconds_left));
        policy.limits.address_space_bytes = std::size_t{3} << 30;
        policy.limits.file_size_bytes = budget.compile_bytes_per_stage - written;
        policy.limits.output_bytes = 64u << 10;
        const SandboxRun run = run_sandboxed(argv, "", policy);
        seconds_left -= run.wall_seconds;
        if (run.timed_out) {
            compiled.failure = "the compiler ran out of time on " + file.filename().string() +
                               ": a stage's files may take " +
                               std::to_string(static_cast<int>(budget.compile_seconds_per_stage)) +
                               " s to compile in all";
            return compiled;
        }
        if (run.exit_code != 0 || run.signal != 0) {
            compiled.failure =
                passed_file_budget(run, bytes_in(objects), budget.compile_bytes_per_stage)
                    ? "the compiler's output for " + file.filename().string() + " passed the " +
                          mebibytes(budget.compile_bytes_per_stage) + " a stage's objects may take"
                    : first_lines(with_repository_paths(run.errors + run.output, work));
            if (compiled.failure.empty())
                compiled.failure = "the compiler failed without a message";
            return compiled;
        }
        if (cache) cache->keep(file, object);
        compiled.objects.push_back(object);
    }
    return compiled;
}

// After the link: the probe and its folder are the grader's again, and the program can be run
// but not read by others, which makes a running probe undumpable: no program of another run can
// open it through /proc/PID/exe.
void seal(const fs::path& program) {
    // Only a regular file in a real folder: fs::permissions follows links, and a link put in the
    // grader's way must not turn a chmod onto another file.
    if (!fs::is_regular_file(fs::symlink_status(program)) ||
        !fs::is_directory(fs::symlink_status(program.parent_path()))) {
        throw std::runtime_error(program.string() + ": not a program the linker made");
    }
    for (const fs::path& path : {program, program.parent_path()}) {
        reclaim(path);
        fs::permissions(path,
                        fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    }
}

// A stage builds on the stages below it and base/, never on a later stage or on what runs the
// stages (ARCHITECTURE.md, "Layers"). A probe links every other stage's reference and the renderer,
// so stage 7's file could call stage 9's reference, which does stage 7's work when nothing
// transmits, and earn stage 7's points with it. So a stage's objects are linked once more, alone
// with the references of the stages below and base/: a call to anything else is an undefined
// reference there, which the linker names with the file that makes it. Empty where there is none,
// or where the link fails for another reason, which the probe's own link then reports.
// binutils' nm, beside the compiler the toolchain names (its real path, past the links).
fs::path nm_program(const ProbeToolchain& toolchain) {
    const fs::path nm = fs::canonical(toolchain.compiler).parent_path() / "nm";
    if (!fs::is_regular_file(nm)) {
        throw std::runtime_error("no nm beside " + toolchain.compiler.string() +
                                 ": the grader needs binutils' nm to read a stage's objects");
    }
    return nm;
}

// The symbols `objects` refer to weakly and do not define: a weak reference that nothing defines
// links as a null address, so the layer link below would pass one to a later stage's function,
// which the probe's own link then binds to the reference. Read by nm in the sandbox: the objects
// are the submission's.
std::vector<std::string> weak_references(const std::vector<fs::path>& objects,
                                         const ProbeToolchain& toolchain) {
    std::vector<std::string> argv = {nm_program(toolchain).string(), "-P", "--undefined-only"};
    if (!toolchain.nm_plugin.empty()) {
        argv.push_back("--plugin");
        argv.push_back(toolchain.nm_plugin.string());
    }
    for (const fs::path& object : objects)
        argv.push_back(object.string());
    SandboxPolicy policy;
    policy.read_only = {objects.front().parent_path()};
    policy.working_directory = objects.front().parent_path();
    policy.limits.cpu_seconds = 20;
    policy.limits.wall = std::chrono::seconds(40);
    policy.limits.output_bytes = 4u << 20;
    const SandboxRun run = run_sandboxed(argv, "", policy);
    std::vector<std::string> weak;
    std::istringstream lines(run.output);
    // POSIX format: "name type", type w or v for a weak reference
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string name;
        std::string type;
        if (words >> name >> type && (type == "w" || type == "v")) weak.push_back(name);
    }
    return weak;
}

// A symbol's name as C++ writes it, or as it is where it is no C++ name.
std::string demangled(const std::string& name) {
    int status = 0;
    char* text = abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status);
    const std::string readable = status == 0 && text ? text : name;
    std::free(text);
    return readable;
}

std::string layer_failure(const CompiledStage& stage, const StagedToolchain& staged,
                          const ProbeToolchain& toolchain, const fs::path& work) {
    if (stage.objects.empty()) return "";
    SandboxPolicy policy;
    policy.read_only = {staged.common, stage.objects.front().parent_path()};
    // No start files: nothing here calls main, and nothing is run.
    std::vector<std::string> argv = {toolchain.compiler.string(), "-nostartfiles", "-o", ""};
    for (const fs::path& object : stage.objects)
        argv.push_back(object.string());
    for (auto it = staged.stage_libraries.rbegin(); it != staged.stage_libraries.rend(); ++it) {
        if (it->first >= stage.number) continue;
        argv.push_back(it->second.string());
        policy.read_only.push_back(it->second.parent_path());
    }
    argv.insert(argv.end(), staged.base_libraries.begin(), staged.base_libraries.end());
    argv.insert(argv.end(), toolchain.link_flags.begin(), toolchain.link_flags.end());
    // A weak reference must be defined here too, as a call is
    for (const std::string& name : weak_references(stage.objects, toolchain))
        argv.push_back("-Wl,--require-defined=" + name);
    const fs::path folder = staged.common.parent_path() / "layers" / std::to_string(stage.number);
    fs::create_directories(folder);
    argv[3] = (folder / "stage").string();
    policy.writable = folder;
    policy.working_directory = folder;
    policy.limits.cpu_seconds = 60;
    policy.limits.wall = std::chrono::seconds(120);
    policy.limits.file_size_bytes = std::uintmax_t{256} << 20;
    policy.limits.output_bytes = 64u << 10;
    const SandboxRun run = run_sandboxed(argv, "", policy);
    const std::string output = run.errors + run.output;
    std::string calls;
    std::istringstream lines(with_repository_paths(output, work));
    // Only raystep's own functions count: without start files, what they define (__dso_handle,
    // which a static object's destructor needs) is missing too, and the system's functions are
    // no stage's work
    for (std::string line; std::getline(lines, line);) {
        if (line.find("undefined reference") != std::string::npos &&
            line.find("raystep::") != std::string::npos) {
            calls += line + "\n";
        }
        // "required symbol `_ZN...' not defined", for a weak reference
        const std::size_t open = line.find("required symbol `");
        const std::size_t close = line.find("' not defined");
        if (open != std::string::npos && close != std::string::npos && close > open) {
            const std::size_t from = open + std::string("required symbol `").size();
            const std::string name = demangled(line.substr(from, close - from));
            if (name.find("raystep::") != std::string::npos)
                calls += "a weak reference to `" + name + "'\n";
        }
    }
    if (calls.empty()) return "";
    return "stage " + std::to_string(stage.number) +
           " calls what neither base/ nor the stages below it define (a stage builds only on "
           "those, ARCHITECTURE.md, \"Layers\", and the grader links their reference), so "
           "neither a later stage's function nor a helper in another stage's file is there to "
           "call:\n" +
           first_lines(calls);
}

BuiltProbe link_probe(const std::vector<const CompiledStage*>& submitted,
                      const StagedToolchain& staged, const ProbeToolchain& toolchain,
                      const fs::path& program, const BuildBudget& budget) {
    SandboxPolicy policy;
    policy.read_only.push_back(staged.common);
    std::vector<std::string> argv = {toolchain.compiler.string(), "-o", program.string()};
    argv.insert(argv.end(), staged.objects.begin(), staged.objects.end());
    std::vector<int> from_submission;
    for (const CompiledStage* stage : submitted) {
        from_submission.push_back(stage->number);
        for (const fs::path& object : stage->objects)
            argv.push_back(object.string());
        if (!stage->objects.empty())
            policy.read_only.push_back(stage->objects.front().parent_path());
    }
    // Higher stages call lower ones: a one-pass linker needs them in that order.
    for (auto it = staged.stage_libraries.rbegin(); it != staged.stage_libraries.rend(); ++it) {
        if (std::find(from_submission.begin(), from_submission.end(), it->first) ==
            from_submission.end()) {
            argv.push_back(it->second.string());
            policy.read_only.push_back(it->second.parent_path());
        }
    }
    argv.insert(argv.end(), staged.libraries.begin(), staged.libraries.end());
    argv.insert(argv.end(), toolchain.link_flags.begin(), toolchain.link_flags.end());

    // Linked in work/link, which the sandbox's user can enter, then moved among the probes.
    const fs::path linked =
        staged.common.parent_path() / "out" / program.parent_path().filename() / "probe";
    fs::create_directories(linked.parent_path());
    policy.writable = linked.parent_path();
    policy.working_directory = linked.parent_path();
    argv[2] = linked.string();
    policy.limits.cpu_seconds = 60;
    policy.limits.wall = std::chrono::seconds(120);
    policy.limits.file_size_bytes = budget.link_bytes_per_probe;
    policy.limits.output_bytes = 64u << 10;
    const SandboxRun run = run_sandboxed(argv, "", policy);
    if ((run.exit_code != 0 || run.signal != 0) &&
        passed_file_budget(run, bytes_in(linked.parent_path()), budget.link_bytes_per_probe)) {
        return {std::nullopt, "the linked probe passed the " +
                                  mebibytes(budget.link_bytes_per_probe) + " a probe may take"};
    }
    if (run.exit_code != 0 || run.timed_out) {
        return {std::nullopt, "the link failed: " + first_lines(run.errors + run.output)};
    }
    fs::create_directories(program.parent_path());
    fs::rename(linked, program);
    seal(program);
    return {program, ""};
}

// The reference probe, copied into the submission's probes so that nothing of the build tree need
// be visible to the sandbox's user.
BuiltProbe copy_reference(const fs::path& reference_probe, const fs::path& program) {
    fs::create_directories(program.parent_path());
    copy_file_for_sandbox(reference_probe, program, kSharedProgram);
    seal(program);
    return {program, ""};
}

// The image library module copied into work/image-library, which the sandbox's user may read (the
// path of the copy); empty where the build has none, and a texture's render then fails with the
// loader's message.
fs::path place_image_library(const ProbeToolchain& toolchain, const fs::path& work) {
    if (!fs::is_regular_file(toolchain.image_module)) return {};
    const fs::path folder = work / "image-library";
    fs::create_directories(folder);
    fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
    const fs::path module = folder / toolchain.image_module.filename();
    // Read, not run: dlopen maps it, and a submission looking for a program to exec finds none.
    copy_file_for_sandbox(toolchain.image_module, module, kSharedFile);
    return module;
}

}  // namespace

const BuiltProbe& ProbeSet::stage(int number) const {
    for (const auto& [n, probe] : stages) {
        if (n == number) return probe;
    }
    static const BuiltProbe not_built{std::nullopt, "not built: no check of this grade needed it"};
    return not_built;
}

ProbeSet build_probes(const Submission& submission, const ProbeToolchain& toolchain,
                      const fs::path& reference_probe, const fs::path& work,
                      const ProbesNeeded& needed, int jobs, const fs::path& object_cache,
                      const BuildBudget& budget) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path include = work / "include";
    copy_headers(toolchain.source, include);
    require_sandbox_reaches(include, work);
    const fs::path precompiled = place_precompiled_header(toolchain, work / "precompiled");
    std::optional<ObjectCache> cache;
    if (!object_cache.empty()) cache.emplace(object_cache, toolchain, work);

    // Compile the stages needed `jobs` at a time: each is independent of the others.
    std::vector<const SubmittedStage*> to_compile;
    for (const SubmittedStage& stage : submission.stages) {
        if (needed.pipeline || needed.stages.count(stage.manifest.number) > 0)
            to_compile.push_back(&stage);
    }
    const StagedToolchain staged = stage_toolchain(toolchain, work / "link");
    std::vector<CompiledStage> compiled(to_compile.size());
    run_at_a_time(compiled.size(), jobs, [&](std::size_t s) {
        compiled[s] = compile_stage(*to_compile[s], toolchain, include, precompiled, work,
                                    cache ? &*cache : nullptr, budget);
        if (compiled[s].failure.empty())
            compiled[s].failure = layer_failure(compiled[s], staged, toolchain, work);
    });

    // Link, with the sandbox's user shut out of work/probes where no bubblewrap hides it.
    const fs::path probes = work / "probes";
    fs::create_directories(probes);
    fs::permissions(probes, bubblewrap_available() ? fs::perms::owner_all | fs::perms::group_exec |
                                                         fs::perms::others_exec
                                                   : fs::perms::owner_all);
    ProbeSet set;
    // Each probe's link: the stages it takes from the submission, where it goes, where its result
    // goes (set.stages is filled first, so that the pointers into it hold).
    struct Link {
        std::vector<const CompiledStage*> stages;
        fs::path program;
        BuiltProbe* probe;
    };
    std::vector<Link> links;
    std::vector<const CompiledStage*> all;
    std::string pipeline_failure;
    for (const CompiledStage& stage : compiled) {
        all.push_back(&stage);
        if (!stage.failure.empty()) {
            pipeline_failure += "stage " + std::to_string(stage.number) + " did not compile. ";
        }
        if (needed.stages.count(stage.number) > 0)
            set.stages.push_back({stage.number, BuiltProbe{std::nullopt, stage.failure}});
    }
    for (std::size_t s = 0, k = 0; s < compiled.size(); ++s) {
        if (needed.stages.count(compiled[s].number) == 0) continue;
        BuiltProbe& probe = set.stages[k++].second;
        if (compiled[s].failure.empty()) {
            links.push_back({{&compiled[s]},
                             probes / ("stage" + std::to_string(compiled[s].number)) / "probe",
                             &probe});
        }
    }
    if (!needed.pipeline) {
        set.pipeline.failure = "not built: no check of this grade needed it";
    } else if (pipeline_failure.empty()) {
        links.push_back({all, probes / "pipeline" / "probe", &set.pipeline});
    } else {
        set.pipeline.failure = pipeline_failure;
    }
    run_at_a_time(links.size(), jobs, [&](std::size_t k) {
        *links[k].probe = link_probe(links[k].stages, staged, toolchain, links[k].program, budget);
    });
    if (needed.reference)
        set.reference = copy_reference(reference_probe, probes / "reference" / "probe");
    set.image_library = place_image_library(toolchain, work);
    // The reference stages leave before any probe runs.
    fs::remove_all(work / "link");
    set.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return set;
}

}  // namespace raystep::grade
