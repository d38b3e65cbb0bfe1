#pragma once

#include <vector>

#include "base/image/image.h"

namespace raystep {

// Renders with noise (stage 8's samples) against a converged reference: no two right renders of
// a sampled scene agree pixel for pixel, so the grader's pixel rule (render_rule.h) cannot judge
// them. Instead a scene is rendered at several seeds, each tile's mean colour taken in each
// render, and the mean over renders compared with the reference's mean over its own seeds, in
// standard errors that the renders' own spread gives. A right render passes whatever its seeds;
// a biased one (a light without its cosine, a shadow that ignores occlusion) leaves its tiles
// many standard errors away.

/// What compare_noisy_renders found.
struct NoisyComparison {
    int tiles = 0;
    int tiles_apart = 0;   ///< tiles whose mean is beyond the bound in some channel, or NaN
    double worst_z = 0.0;  ///< the largest |difference| / standard error of any tile and channel
    int worst_i = 0;       ///< the top-left pixel of the worst tile
    int worst_j = 0;
    Color worst_student;  ///< the worst tile's mean over the student's renders, and the reference's
    Color worst_reference;
};

/// How much more the student's renders of a tile may spread than the reference's. A right renderer
/// draws its samples as the reference does, so the two spreads differ by chance alone: a variance
/// ratio of 16 between 8 and 16 renders lies in F(7, 15)'s tail of 7e-6. Without this bound,
/// noise added to any image would widen its own standard error until every tile passed.
inline constexpr double kSpreadRatioBound = 4.0;

/// Per tile of tile x tile pixels (smaller at the right and bottom edges) and channel: the tile's
/// mean in each render, then the difference between the mean of those over `student` and over
/// `reference`, against its standard error s sqrt(1/K_s + 1/K_r), s the larger of the two sets'
/// standard deviations over renders and `deviation_floor` (a tile with no noise, where rounding
/// alone differs). A tile is apart when a channel's |difference| exceeds `bound` standard errors,
/// or when the student's deviation exceeds kSpreadRatioBound times the larger of the reference's
/// and the floor. Throws std::invalid_argument unless both sets hold at least two renders, all of
/// one size.
NoisyComparison compare_noisy_renders(const std::vector<Image>& student,
                                      const std::vector<Image>& reference, int tile, double bound,
                                      double deviation_floor);

/// The mean of renders of one size, pixel by pixel: the converged image a report shows.
Image mean_image(const std::vector<Image>& renders);

/// Per tile of tile x tile pixels (smaller at the right and bottom edges) and channel, the
/// standard deviation over `renders` of the tile's mean in each: an image with a pixel per tile,
/// tile (i0, j0) at (i0 / tile, j0 / tile). What one render's tile means spread around the mean,
/// shipped with a sampled view's reference so that a single render can be judged
/// (compare_render_with_spread). Throws std::invalid_argument unless there are at least two
/// renders, all of one size.
Image tile_deviations(const std::vector<Image>& renders, int tile);

/// One render against a reference's mean over `reference_renders` renders, with `deviations` the
/// reference's tile_deviations: per tile and channel, the difference of the tile's means against
/// its standard error s sqrt(1 + 1/reference_renders), s the tile's deviation or
/// `deviation_floor` when larger; apart beyond `bound`, as compare_noisy_renders. The one render
/// brings no spread of its own, so a render noisier than the reference's has more tiles apart.
/// Throws std::invalid_argument unless the render is the mean's size and `deviations` has a pixel
/// per tile of it.
NoisyComparison compare_render_with_spread(const Image& render, const Image& reference_mean,
                                           const Image& deviations, int reference_renders, int tile,
                                           double bound, double deviation_floor);

}  // namespace raystep
