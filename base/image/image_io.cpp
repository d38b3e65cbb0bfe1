#include "base/image/image_io.h"

#include <stdexcept>
#include <string>

#include <OpenImageIO/imageio.h>

namespace raystep {

namespace {

bool is_float_format(const std::filesystem::path& path) {
    const std::string extension = path.extension().string();
    return extension == ".exr" || extension == ".EXR" || extension == ".hdr" || extension == ".HDR";
}

}  // namespace

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::string name = path.string();
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());

    auto out = OIIO::ImageOutput::create(name);
    if (!out) {
        throw std::runtime_error(name + ": cannot write this image format (" + OIIO::geterror() +
                                 ")");
    }
    const OIIO::TypeDesc stored =
        is_float_format(path) ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    const OIIO::ImageSpec spec(image.width(), image.height(), 3, stored);
    // OpenImageIO converts our floats to the stored type, clamping to [0, 1] for 8-bit.
    if (!out->open(name, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.data()) ||
        !out->close()) {
        throw std::runtime_error(name + ": cannot write image: " + out->geterror());
    }
}

Image read_image(const std::filesystem::path& path) {
    const std::string name = path.string();
    auto in = OIIO::ImageInput::open(name);
    if (!in) throw std::runtime_error(name + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height);

    // Read channels 0..2 (or the single grey channel) as float.
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        throw std::runtime_error(name + ": cannot read image: " + in->geterror());
    }
    for (int j = 0; j < spec.height; ++j) {
        for (int i = 0; i < spec.width; ++i) {
            const std::size_t k = (static_cast<std::size_t>(j) * spec.width + i) * channels;
            image.set(
                i, j,
                channels == 3 ? Color(pixels[k], pixels[k + 1], pixels[k + 2]) : Color(pixels[k]));
        }
    }
    return image;
}

}  // namespace raystep
