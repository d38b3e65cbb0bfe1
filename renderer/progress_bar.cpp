#include "renderer/progress_bar.h"

#include <algorithm>

namespace raystep {

namespace {

constexpr int kBarWidth = 30;

}  // namespace

ProgressBar::ProgressBar(std::string label, std::size_t total, bool enabled, std::FILE* out,
                         std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(std::max<std::size_t>(total, 1)),
      enabled_(enabled),
      out_(out),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(std::size_t done) {
    if (!enabled_) return;
    const double fraction = std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
    const int filled = static_cast<int>(fraction * kBarWidth);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kBarWidth - filled), '-');
    std::fprintf(out_, "\r%s [%s] %3d%%  %.1f s", label_.c_str(), bar.c_str(),
                 static_cast<int>(fraction * 100.0), seconds);
    if (!unit_.empty()) {
        std::fprintf(out_, "  %zu of %zu %s", std::min(done, total_), total_, unit_.c_str());
    }
    std::fflush(out_);
}

void ProgressBar::finish() {
    if (!enabled_) return;
    update(total_);
    abandon();
}

void ProgressBar::abandon() {
    if (!enabled_) return;
    std::fputc('\n', out_);
    std::fflush(out_);
}

}  // namespace raystep
