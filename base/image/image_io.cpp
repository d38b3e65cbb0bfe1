#include "base/image/image_io.h"

#include <string>

#include "base/image/image_library_loader.h"

namespace raystep {

namespace {

bool is_float_format(const std::filesystem::path& path) {
    const std::string extension = path.extension().string();
    return extension == ".exr" || extension == ".EXR" || extension == ".hdr" || extension == ".HDR";
}

// The room read_rgb fills: the image, sized as the file says.
float* image_room(void* context, int width, int height) {
    Image& image = *static_cast<Image*>(context);
    image = Image(width, height);
    return image.data();
}

}  // namespace

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::string name = path.string();
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    throw_on_image_failure(image_library().write_rgb(name.c_str(), image.width(), image.height(),
                                                     image.data(), is_float_format(path)),
                           name + ": ");
}

Image read_image(const std::filesystem::path& path) {
    const std::string name = path.string();
    Image image;
    throw_on_image_failure(image_library().read_rgb(name.c_str(), image_room, &image), name + ": ");
    return image;
}

}  // namespace raystep
