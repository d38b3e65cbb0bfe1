#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/check/ray_case.h"

namespace raystep {

/// Reads a case file: one or more families (docs/case-files.md). Throws InputError naming the
/// file and line for anything malformed: an unknown keyword, a wrong number of fields, a number
/// that does not parse or is not finite (t_max alone may be `inf`), a case without primitives, a
/// missing `end`; and for what would be checked silently wrong: a radius that is not positive, a
/// zero ray direction or plane normal, an expected normal that is not unit length, a file or
/// family without cases, a case number twice in a family, a family name twice in the file (a file
/// without families names the file alone).
std::vector<CaseFamily> read_case_file(const std::filesystem::path& path);

/// The same from text in memory; `name` is what messages call the file.
std::vector<CaseFamily> parse_case_file(const std::string& text, const std::string& name);

/// Every *.cases file directly in `folder`, in name order; none when it holds none.
std::vector<std::filesystem::path> case_files_in(const std::filesystem::path& folder);

/// Writes families in the format read_case_file reads, every double with 17 significant digits
/// so that reading it back gives the same bits.
void write_case_file(std::ostream& out, const std::vector<CaseFamily>& families);

/// One case as the file shows it (from `case` to `end`), for printing a counterexample that can
/// be pasted into a file of its own and rerun.
std::string case_text(const RayCase& ray_case);

}  // namespace raystep
