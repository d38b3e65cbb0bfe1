#include "studies/common/markdown_table.h"

#include <algorithm>
#include <utility>

namespace raystep {

MarkdownTable::MarkdownTable(std::vector<std::string> headers) : headers_(std::move(headers)) {}

void MarkdownTable::add_row(std::vector<std::string> cells) {
    rows_.push_back(std::move(cells));
}

std::string MarkdownTable::text() const {
    // Column widths: every full row's cells, and the first cell of every row
    std::vector<std::size_t> widths;
    for (const std::string& header : headers_)
        widths.push_back(std::max<std::size_t>(header.size(), 3));
    for (const auto& row : rows_) {
        const bool full = row.size() == headers_.size();
        for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) {
            if (full || c == 0) widths[c] = std::max(widths[c], row[c].size());
        }
    }

    const auto line = [&](const std::vector<std::string>& cells) {
        const bool full = cells.size() == headers_.size();
        std::string text = "|";
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const std::string& cell = cells[c];
            const bool spanning = !full && c + 1 == cells.size() && c > 0;
            const std::size_t pad = spanning ? 0 : widths[c] - std::min(widths[c], cell.size());
            text += " ";
            text += c == 0 ? cell + std::string(pad, ' ') : std::string(pad, ' ') + cell;
            text += " |";
        }
        return text + "\n";
    };

    std::string text = line(headers_);
    text += "|";
    for (std::size_t c = 0; c < widths.size(); ++c) {
        // ":---" left-aligns the names, "---:" right-aligns the numbers
        text += c == 0 ? " :" + std::string(widths[c] - 1, '-') + " |"
                       : " " + std::string(widths[c] - 1, '-') + ": |";
    }
    text += "\n";
    for (const auto& row : rows_)
        text += line(row);
    return text;
}

}  // namespace raystep
