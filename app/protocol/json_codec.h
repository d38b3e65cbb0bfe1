#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "app/protocol/probe_json.h"
#include "stages/1_vectors/vectors.h"

namespace raystep::probe {

// Each protocol value's JSON form, chosen by its C++ type: JsonCodec<T>::write and ::read are the
// functions of probe_json.h for that type, so that a typed call (probe_call.h) writes exactly the
// JSON the hand-written queries wrote, and reads it as strictly. Three shapes are built from
// others: a std::vector is an array of its elements, a std::tuple an array of its members in
// order (a call's positional arguments), and a struct that names its fields in JsonFields an
// object of those fields (a call's named arguments).

template <class T>
struct JsonCodec;

/// A struct's fields by name, for the struct's JSON object: specialize with
///   static constexpr auto list = std::make_tuple(json_field("ray", &RayAtQuestion::ray), ...);
template <class T>
struct JsonFields;

template <class Struct, class Member>
struct JsonField {
    const char* name;
    Member Struct::*member;
};

template <class Struct, class Member>
constexpr JsonField<Struct, Member> json_field(const char* name, Member Struct::*member) {
    return {name, member};
}

/// A codec made of a writer and a reader of probe_json.h.
template <class T, Json (*Write)(const T&), T (*Read)(const Json&)>
struct FunctionCodec {
    static Json write(const T& value) { return Write(value); }
    static T read(const Json& j) { return Read(j); }
};

template <>
struct JsonCodec<double> {
    static Json write(double x) { return number(x); }
    static double read(const Json& j) { return number_from(j); }
};

template <>
struct JsonCodec<int> {
    static Json write(int n) { return Json(n); }
    static int read(const Json& j) { return integer_from(j); }
};

template <>
struct JsonCodec<bool> {
    static Json write(bool b) { return Json(b); }
    static bool read(const Json& j) {
        if (!j.is_boolean()) throw std::invalid_argument("expected true or false");
        return j.get<bool>();
    }
};

template <>
struct JsonCodec<Vec3> : FunctionCodec<Vec3, vec3, vec3_from> {};
template <>
struct JsonCodec<Mat4> : FunctionCodec<Mat4, mat4, mat4_from> {};
template <>
struct JsonCodec<Ray> : FunctionCodec<Ray, ray, ray_from> {};
template <>
struct JsonCodec<std::optional<Hit>> : FunctionCodec<std::optional<Hit>, hit, hit_from> {};
template <>
struct JsonCodec<Sphere> : FunctionCodec<Sphere, sphere, sphere_from> {};
template <>
struct JsonCodec<Transform> : FunctionCodec<Transform, transform, transform_from> {};
template <>
struct JsonCodec<TransformOp> : FunctionCodec<TransformOp, transform_op, transform_op_from> {};
template <>
struct JsonCodec<Material> : FunctionCodec<Material, material, material_from> {};
template <>
struct JsonCodec<Attenuation> : FunctionCodec<Attenuation, attenuation, attenuation_from> {};
template <>
struct JsonCodec<PointLight> : FunctionCodec<PointLight, point_light, point_light_from> {};
template <>
struct JsonCodec<DirectionalLight>
    : FunctionCodec<DirectionalLight, directional_light, directional_light_from> {};
template <>
struct JsonCodec<SurfacePoint> : FunctionCodec<SurfacePoint, surface_point, surface_point_from> {};
template <>
struct JsonCodec<LightSample> : FunctionCodec<LightSample, light_sample, light_sample_from> {};
template <>
struct JsonCodec<RayOffset> : FunctionCodec<RayOffset, ray_offset, ray_offset_from> {};

template <class T>
struct JsonCodec<std::vector<T>> {
    static Json write(const std::vector<T>& values) {
        Json list = Json::array();
        for (const T& value : values)
            list.push_back(JsonCodec<T>::write(value));
        return list;
    }
    static std::vector<T> read(const Json& j) {
        if (!j.is_array()) throw std::invalid_argument("expected an array");
        std::vector<T> values;
        values.reserve(j.size());
        for (const Json& element : j)
            values.push_back(JsonCodec<T>::read(element));
        return values;
    }
};

/// A value, or null for none (a miss, no refracted ray).
template <class T>
struct JsonCodec<std::optional<T>> {
    static Json write(const std::optional<T>& value) {
        return value ? JsonCodec<T>::write(*value) : Json(nullptr);
    }
    static std::optional<T> read(const Json& j) {
        if (j.is_null()) return std::nullopt;
        return JsonCodec<T>::read(j);
    }
};

template <class... T>
struct JsonCodec<std::tuple<T...>> {
    static Json write(const std::tuple<T...>& values) {
        return std::apply(
            [](const T&... value) { return Json::array({JsonCodec<T>::write(value)...}); }, values);
    }
    static std::tuple<T...> read(const Json& j) {
        if (!j.is_array() || j.size() != sizeof...(T)) {
            throw std::invalid_argument("expected an array of " + std::to_string(sizeof...(T)));
        }
        return read_each(j, std::index_sequence_for<T...>{});
    }

  private:
    template <std::size_t... K>
    static std::tuple<T...> read_each(const Json& j, std::index_sequence<K...>) {
        return {JsonCodec<T>::read(j[K])...};
    }
};

/// A struct with JsonFields: an object of its fields.
template <class T, class = decltype(JsonFields<T>::list)>
struct FieldsCodec {
    static Json write(const T& value) {
        Json object = Json::object();
        std::apply(
            [&](const auto&... f) {
                ((object[f.name] = JsonCodec<member_type<decltype(f)>>::write(value.*f.member)),
                 ...);
            },
            JsonFields<T>::list);
        return object;
    }
    static T read(const Json& j) {
        T value{};
        std::apply(
            [&](const auto&... f) {
                ((value.*f.member = JsonCodec<member_type<decltype(f)>>::read(field(j, f.name))),
                 ...);
            },
            JsonFields<T>::list);
        return value;
    }

  private:
    template <class F>
    using member_type = std::decay_t<decltype(std::declval<T&>().*(std::declval<F>().member))>;
};

template <>
struct JsonFields<Frame> {
    static constexpr auto list = std::make_tuple(
        json_field("u", &Frame::u), json_field("v", &Frame::v), json_field("w", &Frame::w));
};
template <>
struct JsonCodec<Frame> : FieldsCodec<Frame> {};

}  // namespace raystep::probe
