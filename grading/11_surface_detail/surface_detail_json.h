#pragma once

#include <array>
#include <utility>

#include "app/protocol/image_json.h"
#include "app/protocol/json_codec.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep::probe {

// Stage 11's values as JSON: a wrap mode by the scene file's words (`repeat`, `clamp`,
// `mirror`), read strictly; the derivatives and the tangent frame by their fields; an image as
// image_json.h writes it.

inline constexpr std::array<std::pair<WrapMode, const char*>, 3> kWrapModeWords{
    {{WrapMode::repeat, "repeat"}, {WrapMode::clamp, "clamp"}, {WrapMode::mirror, "mirror"}}};

template <>
struct JsonCodec<WrapMode> : WordCodec<WrapMode, kWrapModeWords> {};

template <>
struct JsonFields<SurfaceDerivatives> {
    static constexpr auto list = std::make_tuple(json_field("dpdu", &SurfaceDerivatives::dpdu),
                                                 json_field("dpdv", &SurfaceDerivatives::dpdv));
};

template <>
struct JsonFields<TangentFrame> {
    static constexpr auto list = std::make_tuple(json_field("tangent", &TangentFrame::tangent),
                                                 json_field("bitangent", &TangentFrame::bitangent),
                                                 json_field("normal", &TangentFrame::normal));
};

}  // namespace raystep::probe
