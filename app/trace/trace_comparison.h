#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "renderer/pixel_record.h"
#include "renderer/view.h"

namespace raystep {

/// One quantity of a pixel, this build's value beside the reference's.
struct TraceRow {
    std::string quantity;  ///< "the hit's t"
    std::string ours;      ///< "(not reached)" when a stub stopped this build before it
    std::string reference;
    bool same = true;  ///< the values agree; false for a step this build did not reach
};

/// A pixel of this build held against the reference's, step by step in the order of the
/// pipeline, as far as the view goes.
struct TraceComparison {
    std::vector<TraceRow> rows;
    std::optional<std::size_t> first_difference;  ///< the row of the first quantity that differs
    bool stopped = false;  ///< this build did not reach a step the view takes
};

/// Compares `ours` with `reference` as far as the view's reach (pipeline_reach): the camera ray's
/// origin and direction; the hit primitive, its t, normal and barycentrics; each light's reach and
/// term (named by `light_names`, in the records' order) and the local colour; the full colour.
/// Two values are the same when they are within the rounding of the type the reference trace
/// stores them in (stored_roundoff), relative to the quantity's magnitude: the reference's own
/// value could be anywhere in that interval. Rows stop at the first step `ours` did not reach.
/// With `random_colours` (a quad light's samples are in the colours, drawn in whatever order each
/// build draws them) the rows stop after the lights: the local and full colours are left out.
TraceComparison compare_pixel(const PixelRecord& ours, const PixelRecord& reference, View view,
                              const std::vector<std::string>& light_names,
                              bool random_colours = false);

}  // namespace raystep
