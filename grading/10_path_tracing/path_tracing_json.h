#pragma once

#include "app/protocol/json_codec.h"
#include "grading/8_sampling/sampling_json.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep::probe {

// Stage 10's values as JSON: the enums by the scene file's words (`phong`, `ggx`; `hemisphere`,
// `cosine`, `brdf`; `off`, `on`, `mis`), read strictly, and the structs by their fields.

template <>
struct JsonCodec<BrdfModel> {
    static Json write(BrdfModel model);
    static BrdfModel read(const Json& j);
};

template <>
struct JsonCodec<DirectionSampling> {
    static Json write(DirectionSampling sampling);
    static DirectionSampling read(const Json& j);
};

template <>
struct JsonCodec<NextEvent> {
    static Json write(NextEvent next_event);
    static NextEvent read(const Json& j);
};

template <>
struct JsonFields<SurfaceBrdf> {
    static constexpr auto list = std::make_tuple(json_field("model", &SurfaceBrdf::model),
                                                 json_field("diffuse", &SurfaceBrdf::diffuse),
                                                 json_field("specular", &SurfaceBrdf::specular),
                                                 json_field("shininess", &SurfaceBrdf::shininess),
                                                 json_field("roughness", &SurfaceBrdf::roughness));
};

template <>
struct JsonFields<LightDirectionSample> {
    static constexpr auto list =
        std::make_tuple(json_field("direction", &LightDirectionSample::direction),
                        json_field("distance", &LightDirectionSample::distance),
                        json_field("pdf", &LightDirectionSample::pdf),
                        json_field("radiance", &LightDirectionSample::radiance));
};

template <>
struct JsonFields<PathSettings> {
    static constexpr auto list =
        std::make_tuple(json_field("max_depth", &PathSettings::max_depth),
                        json_field("russian_roulette", &PathSettings::russian_roulette),
                        json_field("sampling", &PathSettings::sampling),
                        json_field("next_event", &PathSettings::next_event));
};

}  // namespace raystep::probe
