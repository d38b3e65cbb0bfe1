#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raystep::grade {

/// What went into a release.
struct ReleaseSummary {
    std::size_t files = 0;             ///< copied from the repository
    std::size_t reference_images = 0;  ///< rendered into scenes/
    std::size_t reference_traces = 0;  ///< one per scene rendered, for `raystep trace --compare`
    std::vector<std::string> skipped;  ///< scenes that could not be rendered, and why
    std::size_t public_checks = 0;     ///< case files written into grading/public/
};

/// Writes the student starter repository into `output` (which must not exist, or be empty):
/// the repository at `source` without solutions/, grader/ (the hidden checks, the rubric, the
/// corpus), docs/instructor.md, .git, .ci, the instructor's .github, builds and the libcgal-demo
/// meshes copied into scenes/ (Debian's package, not ours to hand out);
/// release/github/classroom.yml as .github/workflows/classroom.yml, GitHub Classroom's
/// autograding, the release's only workflow; every scene's views, as its
/// `# views:` line names them, rendered with the reference into
/// scenes/<stage>/reference/<scene>.<view>.png, so that students compare their renders with the
/// reference's without having its code; and grading/, the public checks as data with the rubric
/// (release_grading.h), for `raystep grade`. Throws std::runtime_error when `output` is not empty
/// or cannot be written.
ReleaseSummary make_release(const std::filesystem::path& source,
                            const std::filesystem::path& output);

}  // namespace raystep::grade
