#include "app/compare/reference_trace.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>

#include "base/errors/input_error.h"
#include "base/image/image_library_loader.h"

namespace raystep {

namespace fs = std::filesystem;

namespace {

// Every value is a float32 whose mantissa keeps only the bits its quantity needs (stored_bits):
// the bits dropped would be most of the file, and a release carries one for every scene
// (docs/measurements/reference-trace.md has the sizes). Rounded to nearest with b bits kept, a
// value is within 2^-(b+1) of the reference's, relative to its magnitude.
//
// The camera ray keeps 12 bits, 2^-13 = 1.2e-4 relative: the smallest error of a stage that a
// trace is for, a camera ray half a pixel off in a 10 degree field of view 360 pixels high, moves
// the direction by 2.4e-4, twice that. The direction is the largest part of the file, so it keeps
// no more.
constexpr int kRayBits = 12;
// t keeps 16 bits, 2^-17 = 7.6e-6 relative: everything after the hit rests on it, a hit point
// off by a small error in t is where shadow acne starts, and t varies smoothly over a surface, so
// its bits cost less than the direction's.
constexpr int kDistanceBits = 16;
// The normal and the barycentrics keep 10 bits, 2^-11 = 4.9e-4 relative, as a half would: the
// errors a stage makes in them are whole (a normal by M instead of M^-T, unnormalized, flipped;
// beta and gamma swapped), and they vary fastest from pixel to pixel (small spheres, a mesh's
// triangles), where every bit kept costs most.
constexpr int kSurfaceBits = 10;
// A colour keeps 8 bits, 2^-9 = 0.2% relative: its reference image holds 8 bits a channel, so
// the trace shows the colour no coarser than the image does, where the image is bright, and
// finer where it is dark.
constexpr int kColourBits = 8;

// The attribute that marks a file as a reference trace, with the layout's version: a file
// without it is someone else's image.
constexpr const char* kFormatAttribute = "raystep:trace";
constexpr int kFormatVersion = 1;
constexpr const char* kViewAttribute = "raystep:view";
// The digest of the files the reference rendered (base/scene/scene_files.h, scene_digest).
constexpr const char* kSceneDigestAttribute = "raystep:scene_digest";
constexpr const char* kLightsAttribute = "raystep:lights";
// Set when no pixel's full colour differs from its local colour (nothing reflects): the full
// colour is not stored then, and reads back as the local colour (black on a miss).
constexpr const char* kFullIsLocalAttribute = "raystep:full_is_local";

// A primitive index is stored as a float32, exact below 2^24.
constexpr double kIndexLimit = 0x1p24;

struct Channel {
    std::string name;
    TraceQuantity quantity;
};

// The channels of a record that goes as far as `reach`, in the order of the pipeline.
std::vector<Channel> layout(PipelineReach reach, std::size_t lights, bool full_is_local) {
    std::vector<Channel> channels;
    const auto add = [&](const std::string& name, TraceQuantity quantity,
                         std::initializer_list<const char*> parts) {
        for (const char* part : parts)
            channels.push_back({name + part, quantity});
    };
    add("ray.origin", TraceQuantity::camera_origin, {".x", ".y", ".z"});
    add("ray.direction", TraceQuantity::camera_direction, {".x", ".y", ".z"});
    if (reach == PipelineReach::camera_ray) return channels;
    add("hit", TraceQuantity::primitive, {".kind", ".index"});
    add("hit.t", TraceQuantity::t, {""});
    add("hit.normal", TraceQuantity::normal, {".x", ".y", ".z"});
    add("hit", TraceQuantity::barycentrics, {".beta", ".gamma"});
    if (reach == PipelineReach::closest_hit) return channels;
    for (std::size_t k = 0; k < lights; ++k) {
        add("light" + std::to_string(k), TraceQuantity::light_reach, {".reach"});
        add("light" + std::to_string(k) + ".term", TraceQuantity::light_term, {".R", ".G", ".B"});
    }
    add("local", TraceQuantity::local_colour, {".R", ".G", ".B"});
    if (reach == PipelineReach::shading || full_is_local) return channels;
    add("full", TraceQuantity::full_colour, {".R", ".G", ".B"});
    return channels;
}

// A float32 value rounded to nearest with only `bits` of its 23 mantissa bits kept, as its bit
// pattern: rounding the magnitude's pattern is rounding the value, a carry into the exponent
// included.
std::uint32_t rounded_bits(float value, int bits) {
    std::uint32_t pattern = 0;
    std::memcpy(&pattern, &value, sizeof value);
    if (bits >= 23) return pattern;
    const std::uint32_t dropped = 23u - static_cast<std::uint32_t>(bits);
    return (pattern + (1u << (dropped - 1u))) & ~((1u << dropped) - 1u);
}

// The rounded values are stored losslessly but not as they are: the low bits of a float32 are
// noise to the EXR ZIP compressor, which then packs a smooth quantity little better than a noisy
// one (docs/measurements/reference-trace.md). Each channel's bit pattern is predicted from its
// neighbours before it, the one to the left (a), above (b) and above-left (c), by the median edge
// detector of LOCO-I (JPEG-LS): min(a, b) or max(a, b) where c says an edge runs between them, else
// a + b - c, exact on a quantity linear in the pixel's position. Only the prediction's error is
// stored, zigzag-coded so that small errors of either sign have zero high bytes: on smooth
// quantities it is a few units and ZIP packs it tightly, and an edge costs one pixel, not the two
// or three of a prediction along the row alone. The first row and column take the missing
// neighbours as 0.
std::uint32_t predicted(const std::vector<std::uint32_t>& bits, std::size_t width,
                        std::size_t stride, std::size_t channel, std::size_t pixel) {
    const std::size_t i = pixel % width;
    const auto at = [&](std::size_t p) -> std::int64_t { return bits[p * stride + channel]; };
    const std::int64_t a = i > 0 ? at(pixel - 1) : 0;
    const std::int64_t b = pixel >= width ? at(pixel - width) : 0;
    const std::int64_t c = i > 0 && pixel >= width ? at(pixel - width - 1) : 0;
    if (c >= std::max(a, b)) return static_cast<std::uint32_t>(std::min(a, b));
    if (c <= std::min(a, b)) return static_cast<std::uint32_t>(std::max(a, b));
    return static_cast<std::uint32_t>(a + b - c);
}

// Replaces one channel's bit patterns by their zigzag-coded prediction errors, last pixel first,
// so that each prediction still sees the patterns it was made from.
void to_residuals(std::vector<std::uint32_t>& bits, std::size_t width, std::size_t stride,
                  std::size_t channel) {
    for (std::size_t pixel = bits.size() / stride; pixel-- > 0;) {
        const std::uint32_t residual =
            bits[pixel * stride + channel] - predicted(bits, width, stride, channel, pixel);
        // zigzag: 0, -1, 1, -2, ... become 0, 1, 2, 3, ...
        bits[pixel * stride + channel] = (residual << 1) ^ (0u - (residual >> 31));
    }
}

// The inverse of to_residuals, first pixel first.
void from_residuals(std::vector<std::uint32_t>& bits, std::size_t width, std::size_t stride,
                    std::size_t channel) {
    for (std::size_t pixel = 0; pixel < bits.size() / stride; ++pixel) {
        const std::uint32_t coded = bits[pixel * stride + channel];
        const std::uint32_t residual = (coded >> 1) ^ (0u - (coded & 1u));
        bits[pixel * stride + channel] = residual + predicted(bits, width, stride, channel, pixel);
    }
}

// A hit's kind as stored: 0 for a miss, 1 + PrimitiveKind for a hit.
float kind_code(const std::optional<PrimitiveHit>& hit) {
    return hit ? 1.0f + static_cast<float>(hit->kind) : 0.0f;
}

// One record as the values of the layout's channels. A miss stores zeros past its kind.
void encode(const PixelRecord& record, PipelineReach reach, std::size_t lights, bool full_is_local,
            float* out) {
    const auto put = [&](const Vec3& v) {
        for (int c = 0; c < 3; ++c)
            *out++ = static_cast<float>(v[c]);
    };
    const Ray ray = record.camera_ray.value_or(Ray{});
    put(ray.origin);
    put(ray.direction);
    if (reach == PipelineReach::camera_ray) return;
    const PrimitiveHit hit = record.hit.value_or(PrimitiveHit{Hit{0.0, Vec3(0.0)}, {}, 0});
    if (static_cast<double>(hit.index) >= kIndexLimit) {
        throw std::runtime_error("primitive " + std::to_string(hit.index) +
                                 " is past what a reference trace stores exactly (2^24)");
    }
    *out++ = kind_code(record.hit);
    *out++ = static_cast<float>(hit.index);
    *out++ = static_cast<float>(hit.hit.t);
    put(hit.hit.normal);
    *out++ = static_cast<float>(hit.hit.beta);
    *out++ = static_cast<float>(hit.hit.gamma);
    if (reach == PipelineReach::closest_hit) return;
    for (std::size_t k = 0; k < lights; ++k) {
        const LightRecord light = k < record.lights.size() ? record.lights[k] : LightRecord{};
        *out++ = static_cast<float>(light.reach);
        put(light.term);
    }
    put(record.local.value_or(Color(0.0)));
    if (reach == PipelineReach::shading || full_is_local) return;
    put(record.full.value_or(Color(0.0)));
}

// Reads one pixel's channels back into a record; `at` names the pixel in an error.
class Decoder {
  public:
    Decoder(const float* values, const std::string& file, std::size_t pixel, int width)
        : in_(values), file_(file), pixel_(pixel), width_(static_cast<std::size_t>(width)) {}

    double next() { return static_cast<double>(*in_++); }

    Vec3 vector() {
        const double x = next(), y = next(), z = next();
        return {x, y, z};
    }

    // A whole number in [0, limit), or an error naming the channel.
    int whole(const char* channel, double limit) {
        const double value = next();
        if (!(value >= 0.0 && value < limit && value == std::floor(value))) {
            throw InputError(file_, 0,
                             "pixel (" + std::to_string(pixel_ % width_) + ", " +
                                 std::to_string(pixel_ / width_) + "): " + channel + " is " +
                                 std::to_string(value) +
                                 ", which no reference trace holds (truncated or foreign data)");
        }
        return static_cast<int>(value);
    }

  private:
    const float* in_;
    const std::string& file_;
    std::size_t pixel_;
    std::size_t width_;
};

PixelRecord decode_pixel_record(const float* values, PipelineReach reach, std::size_t lights,
                                bool full_is_local, const std::string& file, std::size_t pixel,
                                int width) {
    Decoder in(values, file, pixel, width);
    PixelRecord record;
    Ray ray;
    ray.origin = in.vector();
    ray.direction = in.vector();
    record.camera_ray = ray;
    if (reach == PipelineReach::camera_ray) return record;
    const int kind = in.whole("hit.kind", 4.0);
    const int index = in.whole("hit.index", kIndexLimit);
    Hit hit{in.next(), in.vector()};
    hit.beta = in.next();
    hit.gamma = in.next();
    record.hit_searched = true;
    if (kind > 0)
        record.hit = PrimitiveHit{hit, static_cast<PrimitiveKind>(kind - 1),
                                  static_cast<std::size_t>(index)};
    if (reach == PipelineReach::closest_hit) return record;
    for (std::size_t k = 0; k < lights; ++k) {
        LightRecord light;
        light.reach = static_cast<LightReach>(in.whole("a light's reach", 3.0));
        light.term = in.vector();
        if (record.hit) record.lights.push_back(light);
    }
    const Color local = in.vector();
    if (record.hit) record.local = local;
    if (reach == PipelineReach::shading) return record;
    record.full = full_is_local ? record.local.value_or(Color(0.0)) : in.vector();
    return record;
}

}  // namespace

int stored_bits(TraceQuantity quantity) {
    switch (quantity) {
        case TraceQuantity::primitive:
        case TraceQuantity::light_reach:
            return 23;
        case TraceQuantity::light_term:
        case TraceQuantity::local_colour:
        case TraceQuantity::full_colour:
            return kColourBits;
        case TraceQuantity::camera_origin:
        case TraceQuantity::camera_direction:
            return kRayBits;
        case TraceQuantity::t:
            return kDistanceBits;
        case TraceQuantity::normal:
        case TraceQuantity::barycentrics:
            return kSurfaceBits;
    }
    return 23;
}

double stored_value(double value, TraceQuantity quantity) {
    const std::uint32_t pattern = rounded_bits(static_cast<float>(value), stored_bits(quantity));
    float stored = 0.0f;
    std::memcpy(&stored, &pattern, sizeof stored);
    return static_cast<double>(stored);
}

double stored_roundoff(TraceQuantity quantity) {
    if (quantity == TraceQuantity::primitive || quantity == TraceQuantity::light_reach) return 0.0;
    // Rounding to float32 first, then to the bits kept.
    return std::ldexp(1.0, -(stored_bits(quantity) + 1)) + std::ldexp(1.0, -24);
}

void write_reference_trace(const fs::path& path, int width, int height, View view,
                           std::size_t lights, const std::vector<PixelRecord>& pixels,
                           const std::string& scene_digest) {
    const PipelineReach reach = pipeline_reach(view);
    const bool full_is_local =
        reach == PipelineReach::full_colour &&
        std::all_of(pixels.begin(), pixels.end(), [](const PixelRecord& record) {
            return record.full == std::optional<Color>(record.local.value_or(Color(0.0)));
        });
    const std::vector<Channel> channels = layout(reach, lights, full_is_local);
    const std::size_t count = channels.size();
    if (pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
        throw std::runtime_error(path.string() + ": " + std::to_string(pixels.size()) +
                                 " records for a " + std::to_string(width) + " x " +
                                 std::to_string(height) + " image");
    }
    std::vector<float> values(pixels.size() * count);
    for (std::size_t p = 0; p < pixels.size(); ++p)
        encode(pixels[p], reach, lights, full_is_local, values.data() + p * count);
    std::vector<std::uint32_t> bits(values.size());
    for (std::size_t c = 0; c < count; ++c) {
        const int kept = stored_bits(channels[c].quantity);
        for (std::size_t p = 0; p < pixels.size(); ++p)
            bits[p * count + c] = rounded_bits(values[p * count + c], kept);
        to_residuals(bits, static_cast<std::size_t>(width), count, c);
    }

    std::vector<const char*> names;
    for (const Channel& channel : channels)
        names.push_back(channel.name.c_str());
    const std::string view_text(view_name(view));
    const RaystepIntAttribute ints[] = {{kFormatAttribute, kFormatVersion},
                                        {kLightsAttribute, static_cast<int>(lights)},
                                        {kFullIsLocalAttribute, full_is_local ? 1 : 0}};
    const RaystepStringAttribute strings[] = {{kViewAttribute, view_text.c_str()},
                                              {kSceneDigestAttribute, scene_digest.c_str()}};
    const RaystepChannelImage image = {width,           height,      static_cast<int>(count),
                                       names.data(),    bits.data(), ints,
                                       std::size(ints), strings,     std::size(strings)};

    fs::create_directories(path.parent_path().empty() ? fs::path(".") : path.parent_path());
    throw_on_image_failure(image_library().write_channels(path.string().c_str(), &image),
                           path.string() + ": cannot write: ");
}

ReferenceTrace read_reference_trace(const fs::path& path) {
    const std::string file = path.string();
    const RaystepImageLibraryTable& library = image_library();
    RaystepImageInput* opened = nullptr;
    if (const char* failure = library.open_input(file.c_str(), &opened)) {
        throw InputError(file, 0, "cannot read it: " + std::string(failure));
    }
    const std::unique_ptr<RaystepImageInput, void (*)(RaystepImageInput*)> in(opened,
                                                                              library.close_input);
    int width = 0;
    int height = 0;
    int channel_count = 0;
    int all_uint32 = 0;
    library.input_shape(in.get(), &width, &height, &channel_count, &all_uint32);
    if (library.input_int_attribute(in.get(), kFormatAttribute, 0) != kFormatVersion) {
        throw InputError(file, 0,
                         "not a raystep reference trace (no " + std::string(kFormatAttribute) +
                             " " + std::to_string(kFormatVersion) + " attribute)");
    }
    const std::optional<View> view =
        parse_view(library.input_string_attribute(in.get(), kViewAttribute));
    const int lights = library.input_int_attribute(in.get(), kLightsAttribute, -1);
    if (!view || lights < 0 || width <= 0 || height <= 0) {
        throw InputError(file, 0, "its view, light count or size is missing or wrong");
    }
    const PipelineReach reach = pipeline_reach(*view);
    const bool full_is_local = library.input_int_attribute(in.get(), kFullIsLocalAttribute, 0) != 0;
    const std::vector<Channel> channels =
        layout(reach, static_cast<std::size_t>(lights), full_is_local);
    std::vector<std::string> names;
    for (int c = 0; c < channel_count; ++c)
        names.emplace_back(library.input_channel_name(in.get(), c));
    std::vector<int> position;
    for (const Channel& channel : channels) {
        const auto found = std::find(names.begin(), names.end(), channel.name);
        if (found == names.end()) throw InputError(file, 0, "it has no channel " + channel.name);
        position.push_back(static_cast<int>(found - names.begin()));
    }

    const std::size_t stride = static_cast<std::size_t>(channel_count);
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<std::uint32_t> bits(size * stride);
    if (!all_uint32) {
        throw InputError(file, 0, "not a raystep reference trace (its channels are not uint32)");
    }
    if (const char* failure = library.read_channels(in.get(), bits.data())) {
        throw InputError(file, 0, "cannot read its pixels (truncated?): " + std::string(failure));
    }
    std::vector<float> values(size * stride);
    for (const int at : position) {
        const std::size_t channel = static_cast<std::size_t>(at);
        from_residuals(bits, static_cast<std::size_t>(width), stride, channel);
        for (std::size_t p = 0; p < size; ++p)
            std::memcpy(&values[p * stride + channel], &bits[p * stride + channel], sizeof(float));
    }

    ReferenceTrace trace;
    trace.width = width;
    trace.height = height;
    trace.view = *view;
    trace.scene_digest = library.input_string_attribute(in.get(), kSceneDigestAttribute);
    trace.lights = static_cast<std::size_t>(lights);
    trace.pixels.reserve(size);
    std::vector<float> ordered(channels.size());
    for (std::size_t p = 0; p < size; ++p) {
        for (std::size_t c = 0; c < channels.size(); ++c)
            ordered[c] = values[p * stride + static_cast<std::size_t>(position[c])];
        trace.pixels.push_back(decode_pixel_record(ordered.data(), reach, trace.lights,
                                                   full_is_local, file, p, width));
    }
    return trace;
}

}  // namespace raystep
