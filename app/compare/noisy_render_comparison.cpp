#include "app/compare/noisy_render_comparison.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raystep {

namespace {

void check_set(const std::vector<Image>& renders, const Image& first, const char* which) {
    if (renders.size() < 2) {
        throw std::invalid_argument(std::string("compare_noisy_renders: fewer than two ") + which +
                                    " renders");
    }
    for (const Image& image : renders) {
        if (image.width() != first.width() || image.height() != first.height()) {
            throw std::invalid_argument(std::string("compare_noisy_renders: ") + which +
                                        " renders of different sizes");
        }
    }
}

// Each render's mean colour over the tile at (i0, j0).
std::vector<Color> tile_means(const std::vector<Image>& renders, int i0, int j0, int tile) {
    std::vector<Color> means;
    for (const Image& image : renders) {
        const int i1 = std::min(i0 + tile, image.width());
        const int j1 = std::min(j0 + tile, image.height());
        Color sum(0.0);
        for (int j = j0; j < j1; ++j) {
            for (int i = i0; i < i1; ++i)
                sum += image.at(i, j);
        }
        means.push_back(sum / static_cast<double>((i1 - i0) * (j1 - j0)));
    }
    return means;
}

struct Spread {
    double mean = 0.0;
    double deviation = 0.0;
};

Spread spread(const std::vector<Color>& values, int channel) {
    const double n = static_cast<double>(values.size());
    double sum = 0.0;
    for (const Color& v : values)
        sum += v[channel];
    const double mean = sum / n;
    double squares = 0.0;
    for (const Color& v : values)
        squares += (v[channel] - mean) * (v[channel] - mean);
    return {mean, std::sqrt(squares / (n - 1.0))};
}

// Counts a tile judged with the largest z of its channels, keeping the worst.
void count_tile(NoisyComparison& result, bool apart, double tile_z, int i0, int j0,
                const Color& student_mean, const Color& reference_mean) {
    ++result.tiles;
    if (apart) ++result.tiles_apart;
    // A NaN is the worst there is, and stays so.
    const bool worse = std::isnan(tile_z) ? !std::isnan(result.worst_z) : tile_z > result.worst_z;
    if (result.tiles == 1 || worse) {
        result.worst_z = tile_z;
        result.worst_i = i0;
        result.worst_j = j0;
        result.worst_student = student_mean;
        result.worst_reference = reference_mean;
    }
}

int tiles_across(int pixels, int tile) {
    return (pixels + tile - 1) / tile;
}

}  // namespace

NoisyComparison compare_noisy_renders(const std::vector<Image>& student,
                                      const std::vector<Image>& reference, int tile, double bound,
                                      double deviation_floor) {
    if (student.empty() || reference.empty() || tile < 1) {
        throw std::invalid_argument("compare_noisy_renders: nothing to compare");
    }
    const Image& first = reference.front();
    check_set(student, first, "student");
    check_set(reference, first, "reference");
    const double ks = static_cast<double>(student.size());
    const double kr = static_cast<double>(reference.size());
    NoisyComparison result;
    for (int j0 = 0; j0 < first.height(); j0 += tile) {
        for (int i0 = 0; i0 < first.width(); i0 += tile) {
            const std::vector<Color> s = tile_means(student, i0, j0, tile);
            const std::vector<Color> r = tile_means(reference, i0, j0, tile);
            bool apart = false;
            double tile_z = 0.0;
            Color student_mean;
            Color reference_mean;
            for (int c = 0; c < 3; ++c) {
                const Spread a = spread(s, c);
                const Spread b = spread(r, c);
                student_mean[c] = a.mean;
                reference_mean[c] = b.mean;
                const double deviation = std::max({a.deviation, b.deviation, deviation_floor});
                const double z =
                    std::abs(a.mean - b.mean) / (deviation * std::sqrt(1.0 / ks + 1.0 / kr));
                // Written so that a NaN is apart.
                if (!(z <= bound)) apart = true;
                if (!(a.deviation <= kSpreadRatioBound * std::max(b.deviation, deviation_floor)))
                    apart = true;
                if (std::isnan(z) || z > tile_z) tile_z = z;
            }
            count_tile(result, apart, tile_z, i0, j0, student_mean, reference_mean);
        }
    }
    return result;
}

Image mean_image(const std::vector<Image>& renders) {
    if (renders.empty()) throw std::invalid_argument("mean_image: no renders");
    Image mean(renders.front().width(), renders.front().height());
    for (int j = 0; j < mean.height(); ++j) {
        for (int i = 0; i < mean.width(); ++i) {
            Color sum(0.0);
            for (const Image& image : renders)
                sum += image.at(i, j);
            mean.set(i, j, sum / static_cast<double>(renders.size()));
        }
    }
    return mean;
}

Image tile_deviations(const std::vector<Image>& renders, int tile) {
    if (renders.empty() || tile < 1) throw std::invalid_argument("tile_deviations: no renders");
    const Image& first = renders.front();
    check_set(renders, first, "reference");
    Image deviations(tiles_across(first.width(), tile), tiles_across(first.height(), tile));
    for (int j0 = 0; j0 < first.height(); j0 += tile) {
        for (int i0 = 0; i0 < first.width(); i0 += tile) {
            const std::vector<Color> means = tile_means(renders, i0, j0, tile);
            Color deviation;
            for (int c = 0; c < 3; ++c)
                deviation[c] = spread(means, c).deviation;
            deviations.set(i0 / tile, j0 / tile, deviation);
        }
    }
    return deviations;
}

NoisyComparison compare_render_with_spread(const Image& render, const Image& reference_mean,
                                           const Image& deviations, int reference_renders, int tile,
                                           double bound, double deviation_floor) {
    if (tile < 1 || reference_renders < 1) {
        throw std::invalid_argument("compare_render_with_spread: nothing to compare");
    }
    if (render.width() != reference_mean.width() || render.height() != reference_mean.height()) {
        throw std::invalid_argument(
            "compare_render_with_spread: the render is not the mean's size");
    }
    if (deviations.width() != tiles_across(render.width(), tile) ||
        deviations.height() != tiles_across(render.height(), tile)) {
        throw std::invalid_argument(
            "compare_render_with_spread: the spread has not one pixel per tile");
    }
    const double error_scale = std::sqrt(1.0 + 1.0 / static_cast<double>(reference_renders));
    NoisyComparison result;
    for (int j0 = 0; j0 < render.height(); j0 += tile) {
        for (int i0 = 0; i0 < render.width(); i0 += tile) {
            const Color ours = tile_means({render}, i0, j0, tile).front();
            const Color theirs = tile_means({reference_mean}, i0, j0, tile).front();
            const Color deviation = deviations.at(i0 / tile, j0 / tile);
            bool apart = false;
            double tile_z = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double s = std::max(static_cast<double>(deviation[c]), deviation_floor);
                const double z = std::abs(ours[c] - theirs[c]) / (s * error_scale);
                // Written so that a NaN is apart.
                if (!(z <= bound)) apart = true;
                if (std::isnan(z) || z > tile_z) tile_z = z;
            }
            count_tile(result, apart, tile_z, i0, j0, ours, theirs);
        }
    }
    return result;
}

}  // namespace raystep
