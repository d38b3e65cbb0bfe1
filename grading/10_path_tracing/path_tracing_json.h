#pragma once

#include <array>
#include <utility>

#include "app/protocol/json_codec.h"
#include "grading/8_sampling/sampling_json.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep::probe {

// Stage 10's values as JSON: the enums by the scene file's words (`phong`, `ggx`; `hemisphere`,
// `cosine`, `brdf`; `off`, `on`, `mis`), read strictly, and the structs by their fields.

inline constexpr std::array<std::pair<BrdfModel, const char*>, 2> kBrdfModelWords{
    {{BrdfModel::phong, "phong"}, {BrdfModel::ggx, "ggx"}}};
inline constexpr std::array<std::pair<DirectionSampling, const char*>, 3> kDirectionSamplingWords{
    {{DirectionSampling::hemisphere, "hemisphere"},
     {DirectionSampling::cosine, "cosine"},
     {DirectionSampling::brdf, "brdf"}}};
inline constexpr std::array<std::pair<NextEvent, const char*>, 3> kNextEventWords{
    {{NextEvent::off, "off"}, {NextEvent::on, "on"}, {NextEvent::mis, "mis"}}};

template <>
struct JsonCodec<BrdfModel> : WordCodec<BrdfModel, kBrdfModelWords> {};
template <>
struct JsonCodec<DirectionSampling> : WordCodec<DirectionSampling, kDirectionSamplingWords> {};
template <>
struct JsonCodec<NextEvent> : WordCodec<NextEvent, kNextEventWords> {};

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
