// Writes images through OpenImageIO: EXR keeps linear floats; PNG and JPEG get sRGB 8-bit.
#pragma once

#include <filesystem>

#include "render/image.h"

namespace geodesic {

// Throws std::runtime_error unless the extension names a format write_image supports; lets
// callers reject a bad output name before spending time on a render.
void check_output_format(const std::filesystem::path& path);

// The format follows the extension (.exr, .png, .jpg/.jpeg); an 8-bit format gets the values
// times `scale` (the exposure), an EXR the radiance as it is. Throws std::runtime_error naming
// the path and the reason on failure.
void write_image(const std::filesystem::path& path, const Image& image, float scale = 1);

// Reads any image OpenImageIO understands as linear RGB floats (8-bit files are decoded from
// sRGB). Used by tests and tools.
Image read_image(const std::filesystem::path& path);

}  // namespace geodesic
