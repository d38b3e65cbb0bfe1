#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "app/protocol/probe_json.h"
#include "stages/1_vectors/vectors.h"

namespace raystep::probe {

// Each protocol value's JSON form, chosen by its C++ type: JsonCodec<T>::write and ::read are the
// functions of probe_json.h for that type, so that a typed call (probe_call.h) writes exactly the
// JSON the hand-written queries wrote, and reads it as strictly. Four shapes are built from
// others: a std::vector is an array of its elements, a std::optional its value or null, a
// std::tuple an array of its members in order (a call's positional arguments), and a struct that
// names its fields in JsonFields an object of those fields (a call's named arguments): naming
// them is all such a struct needs.

template <class T, class = void>
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

/// An enum as one of its words, read strictly: `Words` is a constexpr std::array of
/// {value, word} pairs with linkage (an `inline constexpr` beside the enum's codec), e.g.
///   inline constexpr std::array<std::pair<WrapMode, const char*>, 3> kWrapWords{...};
///   template <> struct JsonCodec<WrapMode> : WordCodec<WrapMode, kWrapWords> {};
template <class Enum, const auto& Words>
struct WordCodec {
    static Json write(Enum value) {
        for (const auto& [v, word] : Words) {
            if (v == value) return Json(std::string(word));
        }
        throw std::invalid_argument("a value with no word");
    }
    static Enum read(const Json& j) {
        if (!j.is_string()) throw std::invalid_argument("expected a string");
        const std::string word = j.get<std::string>();
        std::string words;
        for (const auto& [v, w] : Words) {
            if (word == w) return v;
            words += (words.empty() ? "" : ", ") + std::string(w);
        }
        throw std::invalid_argument("unknown word \"" + word + "\": expected one of " + words);
    }
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
struct JsonCodec<std::uint64_t> {
    static Json write(std::uint64_t n) { return Json(n); }
    static std::uint64_t read(const Json& j) {
        if (!j.is_number_unsigned()) throw std::invalid_argument("expected a whole number");
        return j.get<std::uint64_t>();
    }
};

template <>
struct JsonCodec<std::string> {
    static Json write(const std::string& text) { return Json(text); }
    static std::string read(const Json& j) {
        if (!j.is_string()) throw std::invalid_argument("expected a string");
        return j.get<std::string>();
    }
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
struct JsonCodec<Vec2> : FunctionCodec<Vec2, vec2, vec2_from> {};
template <>
struct JsonCodec<Vec3> : FunctionCodec<Vec3, vec3, vec3_from> {};
template <>
struct JsonCodec<Mat4> : FunctionCodec<Mat4, mat4, mat4_from> {};
template <>
struct JsonCodec<Ray> : FunctionCodec<Ray, ray, ray_from> {};
template <>
struct JsonCodec<std::optional<Hit>> : FunctionCodec<std::optional<Hit>, hit, hit_from> {};
template <>
struct JsonCodec<std::optional<PrimitiveHit>>
    : FunctionCodec<std::optional<PrimitiveHit>, primitive_hit, primitive_hit_from> {};
template <>
struct JsonCodec<Sphere> : FunctionCodec<Sphere, sphere, sphere_from> {};
template <>
struct JsonCodec<PrimitiveList>
    : FunctionCodec<PrimitiveList, primitive_list, primitive_list_from> {};
/// A stage-3 case as the probe gets it: the question only, never the expectations.
template <>
struct JsonCodec<RayCase> : FunctionCodec<RayCase, case_question, case_question_from> {};
template <>
struct JsonCodec<CaseAnswer> : FunctionCodec<CaseAnswer, case_answer, case_answer_from> {};
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

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

/// A struct with JsonFields: an object of its fields. A std::optional field is left out where it
/// holds nothing, and holds nothing where it is left out; every other field must be there.
template <class T>
struct FieldsCodec {
    static Json write(const T& value) {
        Json object = Json::object();
        std::apply([&](const auto&... f) { (write_field(object, value.*f.member, f.name), ...); },
                   JsonFields<T>::list);
        return object;
    }
    static T read(const Json& j) {
        T value{};
        std::apply([&](const auto&... f) { (read_field(j, f.name, value.*f.member), ...); },
                   JsonFields<T>::list);
        return value;
    }

  private:
    template <class Member>
    static void write_field(Json& object, const Member& member, const char* name) {
        if constexpr (IsOptional<Member>::value) {
            if (member) object[name] = JsonCodec<typename Member::value_type>::write(*member);
        } else {
            object[name] = JsonCodec<Member>::write(member);
        }
    }
    template <class Member>
    static void read_field(const Json& j, const char* name, Member& member) {
        if constexpr (IsOptional<Member>::value) {
            if (j.is_object() && j.contains(name))
                member = JsonCodec<typename Member::value_type>::read(j.at(name));
        } else {
            member = JsonCodec<Member>::read(field(j, name));
        }
    }
};

template <class T>
struct JsonCodec<T, std::void_t<decltype(JsonFields<T>::list)>> : FieldsCodec<T> {};

template <>
struct JsonFields<Frame> {
    static constexpr auto list = std::make_tuple(
        json_field("u", &Frame::u), json_field("v", &Frame::v), json_field("w", &Frame::w));
};

}  // namespace raystep::probe
