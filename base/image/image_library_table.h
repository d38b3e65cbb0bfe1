#pragma once

#include <stddef.h>
#include <stdint.h>

// The image library's functions as a plain C table: the one thing the module
// (base/image/image_library.cpp, the only code that includes OpenImageIO) and the programs that
// load it (base/image/image_library_loader.h) share. Plain C types only, so that the module and
// the program need not agree on a C++ standard library layout. Every function that can fail
// returns nullptr on success, or the library's message: text owned by the module, valid until
// the next call on the same thread.

#ifdef __cplusplus
extern "C" {
#endif

/// Raised whenever a function below is added, removed or changes its meaning; a program refuses a
/// module built with another version.
#define RAYSTEP_IMAGE_LIBRARY_VERSION 1

/// The name under which the module exports its table (raystep_image_library_table).
#define RAYSTEP_IMAGE_LIBRARY_SYMBOL "raystep_image_library_table"

/// An image file opened for reading; opaque to the program.
typedef struct RaystepImageInput RaystepImageInput;

/// Where read_rgb puts the pixels: `context` is passed back as it was given; the function returns
/// room for width * height * 3 floats, or nullptr to refuse the size.
typedef float* (*RaystepPixelRoom)(void* context, int width, int height);

/// A named integer or string attribute of an image file's header.
typedef struct RaystepIntAttribute {
    const char* name;
    int value;
} RaystepIntAttribute;
typedef struct RaystepStringAttribute {
    const char* name;
    const char* value;
} RaystepStringAttribute;

/// An image of `channels` uint32 channels, interleaved row by row from the top, with its channel
/// names and header attributes, to be written losslessly (zip-compressed where the format can).
typedef struct RaystepChannelImage {
    int width;
    int height;
    int channels;
    const char* const* channel_names;
    const uint32_t* values;
    const RaystepIntAttribute* int_attributes;
    size_t int_attribute_count;
    const RaystepStringAttribute* string_attributes;
    size_t string_attribute_count;
} RaystepChannelImage;

/// The numbers of a comparison of two RGB images, over every channel value.
typedef struct RaystepImageComparison {
    double mean_error;
    double rms_error;
    double psnr;
    double max_error;
} RaystepImageComparison;

typedef struct RaystepImageLibraryTable {
    int version;  ///< RAYSTEP_IMAGE_LIBRARY_VERSION of the module

    /// Writes linear RGB floats in the format the path's extension names: kept as floats when
    /// `keep_floats`, else clamped to [0, 1] and rounded to 8 bits.
    const char* (*write_rgb)(const char* path, int width, int height, const float* rgb,
                             int keep_floats);
    /// Reads any image as linear RGB floats into the room `room` gives (grey is spread to RGB,
    /// alpha dropped).
    const char* (*read_rgb)(const char* path, RaystepPixelRoom room, void* context);
    /// Compares two RGB float images of the same size, as idiff does, counting channel values
    /// that differ by more than `threshold`.
    const char* (*compare_rgb)(int width, int height, const float* a, const float* b,
                               float threshold, RaystepImageComparison* result);

    /// The width in pixels of `text` drawn `size` pixels high with `font` (a path or a font name
    /// looked up in the system's font folders); fails when the font does not open.
    const char* (*text_width)(const char* text, int size, const char* font, int* width);
    /// Draws `text` into RGB floats, vertically centred on row y, starting at column x or centred
    /// on it when `centred`; pixels outside the image are skipped.
    const char* (*draw_text)(float* rgb, int width, int height, int x, int y, const char* text,
                             int size, const char* font, const float colour[3], int centred);

    /// Writes a uint32 channel image to `path`.
    const char* (*write_channels)(const char* path, const RaystepChannelImage* image);

    /// Opens an image file for reading its header and values; *input is set on success only.
    const char* (*open_input)(const char* path, RaystepImageInput** input);
    /// The size and channel count of an open file; `all_uint32` is 1 when every channel is
    /// stored as uint32.
    void (*input_shape)(const RaystepImageInput* input, int* width, int* height, int* channels,
                        int* all_uint32);
    /// The name of channel `channel` (in [0, channels)), valid until close_input.
    const char* (*input_channel_name)(const RaystepImageInput* input, int channel);
    /// An integer attribute of the header, `fallback` when it has none of that name.
    int (*input_int_attribute)(const RaystepImageInput* input, const char* name, int fallback);
    /// A string attribute of the header, "" when it has none; valid until close_input.
    const char* (*input_string_attribute)(const RaystepImageInput* input, const char* name);
    /// Reads every channel of every pixel as uint32 into width * height * channels values.
    const char* (*read_channels)(RaystepImageInput* input, uint32_t* values);
    /// Closes the file and frees `input`.
    void (*close_input)(RaystepImageInput* input);
} RaystepImageLibraryTable;

/// The module's one export: its table, which lives as long as the module is loaded.
typedef const RaystepImageLibraryTable* (*RaystepImageLibraryEntry)(void);

#ifdef __cplusplus
}
#endif
