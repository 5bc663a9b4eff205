#include "viewer/Png.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace viewer
{
namespace
{
struct FileCloser
{
	void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

/// 15-bit bin of a colour: 5 bits per channel.
int binOf(const unsigned char* p) { return (p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3); }

/// Popularity quantization: the (up to) 256 most frequent 5-bit bins, each the mean of its
/// pixels; every bin then maps to its nearest palette entry. Fills `palette` and `indices`.
void quantize(const Image& image, std::vector<png_color>& palette, std::vector<unsigned char>& indices)
{
	const int kBins = 1 << 15;
	std::vector<long> count(kBins, 0), sum(size_t(kBins) * 3, 0);
	const size_t pixels = size_t(image.width) * size_t(image.height);
	for (size_t i = 0; i < pixels; ++i)
	{
		const unsigned char* p = &image.rgb[i * 3];
		const int b = binOf(p);
		++count[size_t(b)];
		for (int c = 0; c < 3; ++c) sum[size_t(b) * 3 + size_t(c)] += p[c];
	}
	std::vector<int> used;
	for (int b = 0; b < kBins; ++b)
		if (count[size_t(b)]) used.push_back(b);
	std::sort(used.begin(), used.end(), [&](int a, int b) { return count[size_t(a)] > count[size_t(b)]; });
	if (used.size() > 256) used.resize(256);
	palette.clear();
	for (int b : used)
	{
		const long n = count[size_t(b)];
		palette.push_back({png_byte(sum[size_t(b) * 3] / n), png_byte(sum[size_t(b) * 3 + 1] / n), png_byte(sum[size_t(b) * 3 + 2] / n)});
	}
	std::vector<int> nearest(kBins, -1);
	indices.resize(pixels);
	for (size_t i = 0; i < pixels; ++i)
	{
		const unsigned char* p = &image.rgb[i * 3];
		int& best = nearest[size_t(binOf(p))];
		if (best < 0)
		{
			long bestDistance = -1;
			for (size_t k = 0; k < palette.size(); ++k)
			{
				const long dr = long(p[0]) - palette[k].red, dg = long(p[1]) - palette[k].green, db = long(p[2]) - palette[k].blue;
				const long d = dr * dr + dg * dg + db * db;
				if (bestDistance < 0 || d < bestDistance)
				{
					bestDistance = d;
					best = int(k);
				}
			}
		}
		indices[i] = (unsigned char)best;
	}
}
}  // namespace

bool writePng(const std::string& path, const Image& image, std::string& error, bool palette)
{
	if (image.width <= 0 || image.height <= 0 || image.rgb.size() != size_t(image.width) * size_t(image.height) * 3)
	{
		error = "empty or inconsistent image";
		return false;
	}
	File file(std::fopen(path.c_str(), "wb"));
	if (!file)
	{
		error = "cannot write '" + path + "': " + std::strerror(errno);
		return false;
	}
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
	png_infop info = png ? png_create_info_struct(png) : nullptr;
	if (!info)
	{
		png_destroy_write_struct(&png, nullptr);
		error = "libpng: out of memory";
		return false;
	}
	std::vector<png_color> colours;
	std::vector<unsigned char> indices;
	if (palette) quantize(image, colours, indices);
	std::vector<png_bytep> rows(size_t(image.height));
	for (int y = 0; y < image.height; ++y)
		rows[size_t(y)] = palette ? &indices[size_t(y) * size_t(image.width)] : const_cast<png_bytep>(image.pixel(0, y));
	if (setjmp(png_jmpbuf(png)))
	{
		png_destroy_write_struct(&png, &info);
		error = "libpng failed writing '" + path + "'";
		return false;
	}
	png_init_io(png, file.get());
	png_set_compression_level(png, 9);
	png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, palette ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_RGB,
				 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	if (palette) png_set_PLTE(png, info, colours.data(), int(colours.size()));
	png_write_info(png, info);
	png_write_image(png, rows.data());
	png_write_end(png, nullptr);
	png_destroy_write_struct(&png, &info);
	return true;
}

bool readPng(const std::string& path, Image& image, std::string& error)
{
	File file(std::fopen(path.c_str(), "rb"));
	if (!file)
	{
		error = "cannot read '" + path + "': " + std::strerror(errno);
		return false;
	}
	png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
	png_infop info = png ? png_create_info_struct(png) : nullptr;
	if (!info)
	{
		png_destroy_read_struct(&png, nullptr, nullptr);
		error = "libpng: out of memory";
		return false;
	}
	if (setjmp(png_jmpbuf(png)))
	{
		png_destroy_read_struct(&png, &info, nullptr);
		error = "'" + path + "' is not a readable PNG";
		return false;
	}
	png_init_io(png, file.get());
	png_read_info(png, info);
	const int type = png_get_color_type(png, info);
	if ((type != PNG_COLOR_TYPE_RGB && type != PNG_COLOR_TYPE_PALETTE) || png_get_bit_depth(png, info) != 8)
	{
		png_destroy_read_struct(&png, &info, nullptr);
		error = "'" + path + "' is not an 8-bit RGB or palette PNG";
		return false;
	}
	if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
	png_read_update_info(png, info);
	image.width = int(png_get_image_width(png, info));
	image.height = int(png_get_image_height(png, info));
	image.rgb.assign(size_t(image.width) * size_t(image.height) * 3, 0);
	std::vector<png_bytep> rows(size_t(image.height));
	for (int y = 0; y < image.height; ++y) rows[size_t(y)] = &image.rgb[size_t(y) * size_t(image.width) * 3];
	png_read_image(png, rows.data());
	png_read_end(png, nullptr);
	png_destroy_read_struct(&png, &info, nullptr);
	return true;
}
}  // namespace viewer
