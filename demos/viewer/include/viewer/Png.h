// Images the offscreen renderer reads back, and PNG files through Debian's libpng.
#pragma once

#include <string>
#include <vector>

namespace viewer
{
/// 8-bit RGB pixels, rows top to bottom.
struct Image
{
	int width = 0, height = 0;
	std::vector<unsigned char> rgb;  ///< width * height * 3

	const unsigned char* pixel(int x, int y) const { return &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3]; }
};

/// Writes `image` as a PNG (maximum compression); false with `error` on failure. With `palette`
/// the colours are reduced to at most 256 first (5 bits per channel, the most frequent kept, each
/// pixel mapped to the nearest): flat-shaded pictures then take about 40% of the bytes.
bool writePng(const std::string& path, const Image& image, std::string& error, bool palette = false);
/// Reads an 8-bit RGB or palette PNG (as writePng writes them) as RGB; false with `error` on failure.
bool readPng(const std::string& path, Image& image, std::string& error);
}  // namespace viewer
