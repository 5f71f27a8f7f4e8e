// Writes and reads images: EXR (OpenEXR) keeps linear floats; PNG (libpng) and JPEG (TurboJPEG)
// get sRGB 8-bit.
#pragma once

#include <filesystem>

#include "render/prepare/image.h"

namespace geodesic {

// Throws std::runtime_error unless the extension names a format write_image supports; lets
// callers reject a bad output name before spending time on a render.
void check_output_format(const std::filesystem::path& path);

// The format follows the extension (.exr, .png, .jpg/.jpeg); an 8-bit format gets the values
// times `scale` (the exposure), an EXR the radiance as it is. Throws std::runtime_error naming
// the path and the reason on failure.
void write_image(const std::filesystem::path& path, const Image& image, float scale = 1);

// Reads an EXR, PNG or JPEG file (told apart by its first bytes) as linear RGB floats (8-bit
// files are decoded from sRGB). Used by tests and tools, and to check a written result.
Image read_image(const std::filesystem::path& path);

}  // namespace geodesic
