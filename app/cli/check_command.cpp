#include "app/cli/check_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>
#include <variant>

#include "app/check/case_file.h"
#include "app/check/case_format.h"
#include "app/check/case_scoring.h"
#include "app/check/check_report.h"
#include "app/check/stage3_methods.h"
#include "app/demo/source_tree.h"
#include "base/errors/input_error.h"

namespace raystep {

namespace {

// Where the cases come from when the command line names none: the stage's cases/ folder in the
// source tree this program was built from.
std::filesystem::path default_case_folder() {
    return source_tree() / "stages" / "3_intersect" / "cases";
}

std::vector<std::filesystem::path> case_files(const CheckArguments& arguments) {
    if (!arguments.files.empty()) return {arguments.files.begin(), arguments.files.end()};
    const std::filesystem::path folder = default_case_folder();
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) {
        throw std::runtime_error("no case files given, and the default folder " + folder.string() +
                                 " does not exist: name case files on the command line");
    }
    std::vector<std::filesystem::path> files = case_files_in(folder);
    if (files.empty()) {
        throw std::runtime_error("no case files given, and the default folder " + folder.string() +
                                 " holds no .cases files");
    }
    return files;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

// The families of every case file, narrowed by --family and --case.
std::vector<CaseFamily> selected_families(const CheckArguments& arguments) {
    std::vector<CaseFamily> families;
    // A name picks a family (--family) and labels its results, across files as within one.
    std::map<std::string, std::filesystem::path> family_files;
    for (const std::filesystem::path& file : case_files(arguments)) {
        std::vector<CaseFamily> read = read_case_file(file);
        for (const CaseFamily& family : read) {
            const auto [first, added] = family_files.emplace(family.name, file);
            if (!added) {
                throw InputError(file.string(), 0,
                                 "family '" + family.name + "' is in " + first->second.string() +
                                     " too: one name, one family");
            }
        }
        std::move(read.begin(), read.end(), std::back_inserter(families));
    }

    if (!arguments.family.empty()) {
        std::vector<std::string> names;
        for (const CaseFamily& family : families)
            names.push_back(family.name);
        families.erase(std::remove_if(families.begin(), families.end(),
                                      [&](const CaseFamily& family) {
                                          return family.name != arguments.family;
                                      }),
                       families.end());
        if (families.empty()) {
            throw std::runtime_error("no family '" + arguments.family +
                                     "' in the case files; the families are: " + joined(names));
        }
    }

    if (arguments.case_index >= 0) {
        const auto wanted = static_cast<std::uint64_t>(arguments.case_index);
        for (CaseFamily& family : families) {
            std::vector<RayCase>& cases = family.cases;
            cases.erase(std::remove_if(cases.begin(), cases.end(),
                                       [&](const RayCase& c) { return c.index != wanted; }),
                        cases.end());
        }
        families.erase(
            std::remove_if(families.begin(), families.end(),
                           [](const CaseFamily& family) { return family.cases.empty(); }),
            families.end());
        if (families.empty()) {
            throw std::runtime_error(
                "no case " + std::to_string(wanted) + " in " +
                (arguments.family.empty() ? "the case files" : "family " + arguments.family));
        }
    }
    return families;
}

std::vector<Stage3Method> selected_methods(const std::string& name) {
    std::vector<Stage3Method> methods = stage3_methods();
    if (name.empty()) return methods;
    methods.erase(std::remove_if(methods.begin(), methods.end(),
                                 [&](const Stage3Method& method) { return method.name != name; }),
                  methods.end());
    return methods;
}

// The command that reruns a counterexample, but for --family, --method and --case.
std::string rerun_command(const CheckArguments& arguments) {
    std::string command = "raystep check --stage " + std::to_string(arguments.stage);
    for (const std::string& file : arguments.files)
        command += " " + file;
    return command;
}

// With --case: what each primitive should give, and what each method gave.

std::string expectation_text(const CasePrimitive& primitive) {
    const Expectation& e = primitive.expected;
    std::string text =
        std::string(e.near_boundary ? "near-boundary " : "") + (e.hit ? "hit" : "miss");
    if (std::isnan(e.t)) return text;
    text += std::string(e.hit ? " at" : ", crossing at") + " t = " + exact_text(e.t) + " within " +
            exact_text(e.t_tolerance) + ", normal " + exact_text(e.normal) + " within " +
            exact_text(e.normal_tolerance);
    if (!std::isnan(e.t_alternative)) {
        text += ", or t = " + exact_text(e.t_alternative) + " with normal " +
                exact_text(e.normal_alternative);
    }
    if (std::holds_alternative<Triangle>(primitive.shape) && !std::isnan(e.beta)) {
        text += ", barycentrics (" + exact_text(e.beta) + ", " + exact_text(e.gamma) + ") within " +
                exact_text(e.barycentric_tolerance);
    }
    return text;
}

std::string hit_text(const std::optional<Hit>& hit, bool triangle) {
    if (!hit) return "miss";
    std::string text = "hit at t = " + exact_text(hit->t) + ", normal " + exact_text(hit->normal);
    if (triangle) {
        text += ", barycentrics (" + exact_text(hit->beta) + ", " + exact_text(hit->gamma) + ")";
    }
    return text;
}

// The answer as a whole when it is an exception, else empty.
std::string exception_text(const CaseAnswer& answer) {
    if (answer.not_implemented) return "not implemented: " + answer.error;
    if (!answer.error.empty()) return "threw: " + answer.error;
    return "";
}

// run_method's answer of closest_hit: the primitive it chose, in the case's numbering, and the hit.
std::string closest_text(const RayCase& ray_case, const CaseAnswer& answer) {
    const std::string failure = exception_text(answer);
    if (!failure.empty()) return failure;
    if (!answer.closest_hit) return "miss";
    const std::size_t k = *answer.closest_primitive;
    const CaseShape& shape = ray_case.primitives[k].shape;
    return "primitive " + std::to_string(k) + " (" + shape_name(shape) +
           "): " + hit_text(answer.closest_hit, std::holds_alternative<Triangle>(shape));
}

// answers[m]: methods[m]'s answer on the case.
void print_case_answers(const CaseFamily& family, const RayCase& ray_case,
                        const std::vector<Stage3Method>& methods,
                        const std::vector<CaseAnswer>& answers) {
    int width = 0;
    for (const Stage3Method& method : methods) {
        width = std::max(width, static_cast<int>(method.name.size()));
    }
    const Ray& ray = ray_case.ray;
    std::printf("case %llu of family %s%s: ray from %s along %s, t in [%s, %s]\n",
                static_cast<unsigned long long>(ray_case.index), family.name.c_str(),
                ray_case.watertight ? " (watertight)" : "", exact_text(ray.origin).c_str(),
                exact_text(ray.direction).c_str(), exact_text(ray.t_min).c_str(),
                exact_text(ray.t_max).c_str());

    for (std::size_t k = 0; k < ray_case.primitives.size(); ++k) {
        const CasePrimitive& primitive = ray_case.primitives[k];
        const bool triangle = std::holds_alternative<Triangle>(primitive.shape);
        std::printf("  primitive %zu (%s): expected %s\n", k, shape_name(primitive.shape),
                    expectation_text(primitive).c_str());
        for (std::size_t m = 0; m < methods.size(); ++m) {
            if (methods[m].kind == Stage3Method::Kind::closest) continue;
            if (!applies_to(methods[m], primitive.shape)) continue;
            const std::string failure = exception_text(answers[m]);
            const std::string got =
                failure.empty() ? hit_text(answers[m].hits[k], triangle) : failure;
            std::printf("    %-*s  %s\n", width, methods[m].name.c_str(), got.c_str());
        }
    }

    for (std::size_t m = 0; m < methods.size(); ++m) {
        if (methods[m].kind != Stage3Method::Kind::closest) continue;
        std::printf("  %-*s  %s\n", width + 2, methods[m].name.c_str(),
                    closest_text(ray_case, answers[m]).c_str());
    }
    std::printf("\n");
}

}  // namespace

CLI::App* add_check_command(CLI::App& app, CheckArguments& arguments) {
    CLI::App* command = app.add_subcommand(
        "check",
        "Run this build's stage functions on ray cases and score them against the "
        "exact answers (docs/case-files.md)");
    command->add_option("--stage", arguments.stage, "The stage to check")
        ->required()
        ->check(CLI::Validator(
            [](std::string& stage) {
                return stage == "3" ? std::string()
                                    : "only stage 3 has case checks so far, not " + stage;
            },
            "3", "stage"));
    command
        ->add_option("files", arguments.files,
                     "Case files (default: every *.cases file in stages/3_intersect/cases/)")
        ->check(CLI::ExistingFile);
    command->add_option("--family", arguments.family, "Check only this family of cases");
    std::vector<std::string> method_names;
    for (const Stage3Method& method : stage3_methods())
        method_names.push_back(method.name);
    command->add_option("--method", arguments.method, "Check only this function of intersect.h")
        ->check(CLI::IsMember(method_names));
    command
        ->add_option("--case", arguments.case_index,
                     "Check only the case with this index, and show each answer beside the "
                     "expectation")
        ->check(CLI::NonNegativeNumber);
    return command;
}

int run_check(const CheckArguments& arguments) {
    const std::vector<CaseFamily> families = selected_families(arguments);
    const std::vector<Stage3Method> methods = selected_methods(arguments.method);

    std::vector<MethodScore> scores;
    for (const CaseFamily& family : families) {
        std::vector<std::vector<CaseAnswer>> answers;  // answers[m][c]: method m on case c
        for (const Stage3Method& method : methods) {
            std::vector<CaseAnswer>& method_answers = answers.emplace_back();
            for (const RayCase& ray_case : family.cases) {
                method_answers.push_back(run_method(method, ray_case));
                // score_family stops at a stub's first answer, so the rest need not run.
                if (method_answers.back().not_implemented) break;
            }
            method_answers.resize(family.cases.size());
            scores.push_back(score_family(method, family, method_answers));
        }
        if (arguments.case_index >= 0) {
            std::vector<CaseAnswer> case_answers;
            for (const std::vector<CaseAnswer>& method_answers : answers) {
                case_answers.push_back(method_answers.front());
            }
            print_case_answers(family, family.cases.front(), methods, case_answers);
        }
    }
    print_check_report(stdout, scores, rerun_command(arguments));

    std::size_t checked = 0;
    std::size_t passed = 0;
    std::set<std::string> stubs;
    for (const MethodScore& score : scores) {
        checked += score.cases;
        passed += score.passed;
        if (score.not_implemented) stubs.insert(score.method);
    }
    const std::string not_implemented =
        stubs.empty()
            ? ""
            : std::to_string(stubs.size()) + (stubs.size() == 1 ? " method is" : " methods are") +
                  " not implemented";
    if (checked == 0) {
        std::printf("\nnothing was checked: %s\n",
                    stubs.empty()
                        ? "no selected case has a primitive that the selected methods test"
                        : not_implemented.c_str());
        return 1;
    }
    std::printf("\n%zu of %zu checks passed (a check is one method on one case)%s%s\n", passed,
                checked, stubs.empty() ? "" : "; ", not_implemented.c_str());
    return passed == checked && stubs.empty() ? 0 : 1;
}

}  // namespace raystep
