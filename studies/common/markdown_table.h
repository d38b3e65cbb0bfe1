#pragma once

#include <string>
#include <vector>

namespace raystep {

/// A table with `|` between its columns, padded so that it lines up on a console and is valid
/// Markdown as it stands: the bench's output pastes into the docs unchanged.
class MarkdownTable {
  public:
    /// Columns named `headers`; the first is left-aligned (names), every other right-aligned
    /// (numbers).
    explicit MarkdownTable(std::vector<std::string> headers);

    /// Adds a row. A row with fewer cells than columns ends there, its last cell standing for the
    /// rest (a message in place of numbers): it is neither padded nor counted in the widths.
    void add_row(std::vector<std::string> cells);

    /// The header, the alignment line and the rows, each line ending in '\n'.
    std::string text() const;

  private:
    std::vector<std::string> headers_;
    std::vector<std::vector<std::string>> rows_;
};

}  // namespace raystep
