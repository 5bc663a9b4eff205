#include "viewer/Png.h"

#include <png.h>

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
}  // namespace

bool writePng(const std::string& path, const Image& image, std::string& error)
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
	std::vector<png_bytep> rows(size_t(image.height));
	for (int y = 0; y < image.height; ++y) rows[size_t(y)] = const_cast<png_bytep>(image.pixel(0, y));
	if (setjmp(png_jmpbuf(png)))
	{
		png_destroy_write_struct(&png, &info);
		error = "libpng failed writing '" + path + "'";
		return false;
	}
	png_init_io(png, file.get());
	png_set_compression_level(png, 9);
	png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
				 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
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
	if (png_get_color_type(png, info) != PNG_COLOR_TYPE_RGB || png_get_bit_depth(png, info) != 8)
	{
		png_destroy_read_struct(&png, &info, nullptr);
		error = "'" + path + "' is not an 8-bit RGB PNG";
		return false;
	}
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
