// The image library module: every use of OpenImageIO in raystep, behind the C table of
// base/image/image_library_table.h. It is a module loaded on first use
// (base/image/image_library_loader.cpp) rather than a library the programs link, because
// OpenImageIO brings about 260 shared libraries whose symbol resolution costs every command its
// startup, even those that read or write no image (docs/measurements/startup.md).

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "base/image/image_library_table.h"

struct RaystepImageInput {
    std::unique_ptr<OIIO::ImageInput> file;
    std::string string_attribute;  // the last one asked for, kept until the next ask
};

namespace {

// The message of the last failure on this thread, returned as the C table's functions promise.
const char* failure(std::string message) {
    thread_local std::string last;
    last = std::move(message);
    return last.c_str();
}

const char* write_rgb(const char* path, int width, int height, const float* rgb, int keep_floats) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return failure("cannot write this image format (" + OIIO::geterror() + ")");
    const OIIO::TypeDesc stored = keep_floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    const OIIO::ImageSpec spec(width, height, 3, stored);
    // OpenImageIO converts the floats to the stored type, clamping to [0, 1] for 8-bit.
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb) || !out->close()) {
        return failure("cannot write image: " + out->geterror());
    }
    return nullptr;
}

const char* read_rgb(const char* path, RaystepPixelRoom room, void* context) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return failure("cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    float* rgb = room(context, spec.width, spec.height);
    if (!rgb) return failure("cannot read image: no room for its size");

    // Read channels 0..2 (or the single grey channel) as float
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<float> pixels(count * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        return failure("cannot read image: " + in->geterror());
    }
    for (std::size_t p = 0; p < count; ++p) {
        for (int c = 0; c < 3; ++c)
            rgb[3 * p + c] = pixels[p * channels + (channels == 3 ? c : 0)];
    }
    return nullptr;
}

OIIO::ImageBuf rgb_buffer(int width, int height, const float* rgb) {
    OIIO::ImageBuf buffer(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    buffer.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb);
    return buffer;
}

const char* compare_rgb(int width, int height, const float* a, const float* b, float threshold,
                        RaystepImageComparison* result) {
    const OIIO::ImageBufAlgo::CompareResults numbers = OIIO::ImageBufAlgo::compare(
        rgb_buffer(width, height, a), rgb_buffer(width, height, b), threshold, threshold);
    result->mean_error = numbers.meanerror;
    result->rms_error = numbers.rms_error;
    result->psnr = numbers.PSNR;
    result->max_error = numbers.maxerror;
    return nullptr;
}

const char* text_width(const char* text, int size, const char* font, int* width) {
    const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, size, font);
    // A font that does not open leaves its message in OpenImageIO: taken here, so that it is
    // returned rather than printed later.
    if (!box.defined())
        return failure("cannot open the font " + std::string(font) + ": " + OIIO::geterror());
    *width = box.width();
    return nullptr;
}

const char* draw_text(float* rgb, int width, int height, int x, int y, const char* text, int size,
                      const char* font, const float colour[3], int centred) {
    // Draw straight into the caller's pixels: an ImageBuf over them copies nothing
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buffer(spec, rgb);
    const auto align_x =
        centred ? OIIO::ImageBufAlgo::TextAlignX::Center : OIIO::ImageBufAlgo::TextAlignX::Left;
    if (!OIIO::ImageBufAlgo::render_text(buffer, x, y, text, size, font, {colour, 3}, align_x,
                                         OIIO::ImageBufAlgo::TextAlignY::Center)) {
        return failure(buffer.geterror());
    }
    return nullptr;
}

const char* write_channels(const char* path, const RaystepChannelImage* image) {
    OIIO::ImageSpec spec(image->width, image->height, image->channels, OIIO::TypeDesc::UINT32);
    spec.channelnames.assign(image->channel_names, image->channel_names + image->channels);
    spec.attribute("compression", "zip");
    for (std::size_t k = 0; k < image->int_attribute_count; ++k)
        spec.attribute(image->int_attributes[k].name, image->int_attributes[k].value);
    for (std::size_t k = 0; k < image->string_attribute_count; ++k) {
        spec.attribute(image->string_attributes[k].name,
                       std::string(image->string_attributes[k].value));
    }
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return failure(OIIO::geterror());
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT32, image->values) ||
        !out->close()) {
        return failure(out->geterror());
    }
    return nullptr;
}

const char* open_input(const char* path, RaystepImageInput** input) {
    auto file = OIIO::ImageInput::open(path);
    if (!file) return failure(OIIO::geterror());
    *input = new RaystepImageInput{std::move(file), {}};
    return nullptr;
}

void input_shape(const RaystepImageInput* input, int* width, int* height, int* channels,
                 int* all_uint32) {
    const OIIO::ImageSpec& spec = input->file->spec();
    *width = spec.width;
    *height = spec.height;
    *channels = spec.nchannels;
    *all_uint32 = spec.format == OIIO::TypeDesc::UINT32 && spec.channelformats.empty();
}

const char* input_channel_name(const RaystepImageInput* input, int channel) {
    return input->file->spec().channelnames[static_cast<std::size_t>(channel)].c_str();
}

int input_int_attribute(const RaystepImageInput* input, const char* name, int fallback) {
    return input->file->spec().get_int_attribute(name, fallback);
}

const char* input_string_attribute(const RaystepImageInput* input, const char* name) {
    auto* owned = const_cast<RaystepImageInput*>(input);
    owned->string_attribute = input->file->spec().get_string_attribute(name);
    return owned->string_attribute.c_str();
}

const char* read_channels(RaystepImageInput* input, uint32_t* values) {
    const int channels = input->file->spec().nchannels;
    if (!input->file->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT32, values)) {
        return failure(input->file->geterror());
    }
    return nullptr;
}

void close_input(RaystepImageInput* input) {
    delete input;
}

constexpr RaystepImageLibraryTable kTable = {
    RAYSTEP_IMAGE_LIBRARY_VERSION,
    write_rgb,
    read_rgb,
    compare_rgb,
    text_width,
    draw_text,
    write_channels,
    open_input,
    input_shape,
    input_channel_name,
    input_int_attribute,
    input_string_attribute,
    read_channels,
    close_input,
};

}  // namespace

#ifdef _WIN32
#define RAYSTEP_IMAGE_LIBRARY_EXPORT __declspec(dllexport)
#else
#define RAYSTEP_IMAGE_LIBRARY_EXPORT __attribute__((visibility("default")))
#endif

extern "C" RAYSTEP_IMAGE_LIBRARY_EXPORT const RaystepImageLibraryTable*
raystep_image_library_table() {
    return &kTable;
}
