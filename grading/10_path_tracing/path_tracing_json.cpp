#include "grading/10_path_tracing/path_tracing_json.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace raystep::probe {

namespace {

template <class Enum, std::size_t N>
Json word_of(Enum value, const std::array<std::pair<Enum, const char*>, N>& words) {
    for (const auto& [v, word] : words) {
        if (v == value) return Json(std::string(word));
    }
    throw std::invalid_argument("a value with no word");
}

template <class Enum, std::size_t N>
Enum value_of(const Json& j, const std::array<std::pair<Enum, const char*>, N>& words,
              const char* what) {
    const std::string word = JsonCodec<std::string>::read(j);
    for (const auto& [v, w] : words) {
        if (word == w) return v;
    }
    throw std::invalid_argument("unknown " + std::string(what) + " \"" + word + "\"");
}

constexpr std::array<std::pair<BrdfModel, const char*>, 2> kModels{
    {{BrdfModel::phong, "phong"}, {BrdfModel::ggx, "ggx"}}};
constexpr std::array<std::pair<DirectionSampling, const char*>, 3> kSamplings{
    {{DirectionSampling::hemisphere, "hemisphere"},
     {DirectionSampling::cosine, "cosine"},
     {DirectionSampling::brdf, "brdf"}}};
constexpr std::array<std::pair<NextEvent, const char*>, 3> kNextEvents{
    {{NextEvent::off, "off"}, {NextEvent::on, "on"}, {NextEvent::mis, "mis"}}};

}  // namespace

Json JsonCodec<BrdfModel>::write(BrdfModel model) {
    return word_of(model, kModels);
}

BrdfModel JsonCodec<BrdfModel>::read(const Json& j) {
    return value_of(j, kModels, "brdf");
}

Json JsonCodec<DirectionSampling>::write(DirectionSampling sampling) {
    return word_of(sampling, kSamplings);
}

DirectionSampling JsonCodec<DirectionSampling>::read(const Json& j) {
    return value_of(j, kSamplings, "importance sampling");
}

Json JsonCodec<NextEvent>::write(NextEvent next_event) {
    return word_of(next_event, kNextEvents);
}

NextEvent JsonCodec<NextEvent>::read(const Json& j) {
    return value_of(j, kNextEvents, "next event estimation");
}

}  // namespace raystep::probe
