// Writes the hostile inputs of tests/reliability/hostile.cmake into one directory: binary garbage, huge
// lines, odd encodings, images whose header lies, scenes with huge counts. They are generated at test time
// rather than committed (binary or large); tests/data/README.md lists each with the behaviour it must
// produce.
#include <stb_image_write.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
fs::path gOut;

void write(const std::string& name, const std::string& bytes) {
    std::ofstream file(gOut / name, std::ios::binary);
    file.write(bytes.data(), std::streamsize(bytes.size()));
    if (!file) throw std::runtime_error("cannot write " + (gOut / name).string());
}

// Deterministic bytes of every value 0..255 (NULs, newlines, high bytes), the same on every run.
std::string garbage(size_t size, uint32_t seed) {
    std::string bytes(size, '\0');
    for (char& c : bytes) {
        seed = seed * 1664525u + 1013904223u;
        c = char(seed >> 24);
    }
    return bytes;
}

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// --- PNG written by hand: any bit depth, and headers that lie ----------------------------------

uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void put32(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xff);
}

void chunk(std::string& png, const char* type, const std::string& data) {
    put32(png, uint32_t(data.size()));
    std::string body = std::string(type, 4) + data;
    png += body;
    put32(png, crc32(body));
}

// A PNG whose IHDR says width x height, and whose IDAT holds `scanlines` (filter byte + pixels
// per row) in a zlib stream of stored (uncompressed) blocks.
std::string png(uint32_t width, uint32_t height, uint8_t bitDepth, uint8_t colorType,
                const std::string& scanlines) {
    std::string out = "\x89PNG\r\n\x1a\n";
    std::string header;
    put32(header, width);
    put32(header, height);
    header += char(bitDepth);
    header += char(colorType);
    header += std::string(3, '\0');  // deflate, adaptive filtering, no interlace
    chunk(out, "IHDR", header);
    std::string zlib = "\x78\x01";
    for (size_t at = 0; at < scanlines.size() || at == 0; at += 65535) {
        size_t length = std::min<size_t>(65535, scanlines.size() - at);
        bool last = at + length >= scanlines.size();
        zlib += char(last ? 1 : 0);
        zlib += char(length & 0xff);
        zlib += char(length >> 8);
        zlib += char(~length & 0xff);
        zlib += char((~length >> 8) & 0xff);
        zlib += scanlines.substr(at, length);
        if (last) break;
    }
    uint32_t a = 1, b = 0;
    for (unsigned char c : scanlines) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    put32(zlib, (b << 16) | a);
    chunk(out, "IDAT", zlib);
    chunk(out, "IEND", "");
    return out;
}

// Scanlines of a width x height image of `bytesPerPixel`, filter 0, a simple gradient.
std::string scanlines(uint32_t width, uint32_t height, uint32_t bytesPerPixel) {
    std::string rows;
    for (uint32_t y = 0; y < height; ++y) {
        rows += '\0';
        for (uint32_t x = 0; x < width * bytesPerPixel; ++x) rows += char((x * 7 + y * 13) & 0xff);
    }
    return rows;
}

void stbPng(const std::string& name, int width, int height, int channels) {
    std::vector<unsigned char> pixels(size_t(width) * size_t(height) * size_t(channels));
    for (size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = (i % size_t(channels) == size_t(channels) - 1 && channels % 2 == 0)
                        ? 128
                        : (unsigned char)(i * 5);
    if (!stbi_write_png((gOut / name).c_str(), width, height, channels, pixels.data(), width * channels))
        throw std::runtime_error("cannot write " + name);
}

// A textured quad whose material's map_Kd is `image`: tex_<name>.obj and tex_<name>.mtl.
void texturedModel(const std::string& name, const std::string& image) {
    write("tex_" + name + ".mtl", "newmtl m\nKd 1 1 1\nmap_Kd " + image + "\n");
    write("tex_" + name + ".obj",
          "mtllib tex_" + name +
              ".mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
              "usemtl m\nf 1/1 2/2 3/3 4/4\n");
}

std::string utf16le(const std::string& ascii) {
    std::string out = "\xff\xfe";
    for (char c : ascii) out += std::string{c, '\0'};
    return out;
}

// A scene of one triangle (tri.obj) and `lights` point lights, or `models` instances of it.
std::string manyLights(size_t lights) {
    std::string json = R"({"models": [{"file": "tri.obj"}], "lights": [)";
    for (size_t i = 0; i < lights; ++i)
        json += std::string(i ? "," : "") + R"({"type": "point", "position": [0, 1, 1], "intensity": 0.001})";
    return json + "]}\n";
}

std::string manyModels(size_t models, const std::string& file = "tri.obj") {
    std::string json = R"({"models": [)";
    for (size_t i = 0; i < models; ++i)
        json += std::string(i ? "," : "") + R"({"file": ")" + file + R"(", "position": [)" +
                std::to_string(i % 100) + ", " + std::to_string(i / 100 % 100) + ", -5]}";
    return json + "]}\n";
}

// A scene of tri.obj with `extra` spliced into its top-level object.
std::string scene(const std::string& extra) {
    return R"({"models": [{"file": "tri.obj"}])" + (extra.empty() ? "" : ", " + extra) + "}\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: hostile_inputs OUTPUT_DIR\n");
        return 2;
    }
    try {
        gOut = argv[1];
        fs::create_directories(gOut);

        // OBJ and MTL.
        write("tri.obj", kTriangle);
        write("garbage.obj", garbage(4096, 1));
        write("garbage.mtl", garbage(4096, 2));
        write("garbage_mtl.obj", std::string("mtllib garbage.mtl\nusemtl m\n") + kTriangle);
        write("empty.mtl", "");
        write("empty_mtl.obj", std::string("mtllib empty.mtl\nusemtl m\n") + kTriangle);
        write("utf16.obj", utf16le(kTriangle));
        write("utf16_nobom.obj", utf16le(kTriangle).substr(2));
        // A UTF-8 byte order mark before the first vertex: tinyobjloader alone drops that line.
        write("utf8_bom.obj", "\xef\xbb\xbf" + std::string(kTriangle));
        write("usemtl_only.obj", "usemtl a\nusemtl b\n");
        write("points_lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\nl 1 2 3\n");
        write("huge_comment.obj", "# " + std::string(1'000'000, 'x') + "\n" + kTriangle);
        write("huge_number.obj", "v 1" + std::string(1'000'000, '0') + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        std::string many = "v";
        while (many.size() < 1'000'000) many += " 0.5";
        write("huge_v_line.obj", many + "\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        write("zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
        write("int_overflow_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n");
        write("quad_bad_index.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 9\n");
        // An L-shaped hexagon (concave at 5) far from the origin: 4 triangles of total area 3.
        write(
            "concave.obj",
            "v 100 100 0\nv 102 100 0\nv 102 101 0\nv 101 101 0\nv 101 102 0\nv 100 102 0\nf 1 2 3 4 5 6\n");
        std::string circle, bigFace = "f";
        for (int i = 0; i < 300; ++i) {
            circle += "v " + std::to_string(std::cos(i * 6.2831853 / 300)) + " " +
                      std::to_string(std::sin(i * 6.2831853 / 300)) + " 0\n";
            bigFace.append(" ").append(std::to_string(i + 1));
        }
        write("polygon300.obj", circle + bigFace + "\n");
        std::string face255 = "f";
        for (int i = 0; i < 255; ++i) face255.append(" ").append(std::to_string(i + 1));
        write("polygon255.obj", circle + face255 + "\n");

        // Textures (each behind a textured quad, tex_<name>.obj).
        stbPng("1x1.png", 1, 1, 4);
        stbPng("16384x1.png", 16384, 1, 4);
        stbPng("16385x1.png", 16385, 1, 4);
        stbPng("grey.png", 16, 16, 1);
        stbPng("grey_alpha.png", 16, 16, 2);
        write("rgb16.png", png(16, 16, 16, 2, scanlines(16, 16, 6)));
        write("header_lies.png", png(4096, 4096, 8, 6, scanlines(4, 4, 4)));
        write("header_huge.png", png(100000, 100000, 8, 6, scanlines(4, 4, 4)));
        write("header_at_limit.png", png(16384, 16384, 8, 6, scanlines(4, 4, 4)));
        std::string whole = png(64, 64, 8, 6, scanlines(64, 64, 4));
        write("truncated.png", whole.substr(0, whole.size() / 2));
        write("empty.png", "");
        write("garbage.png", garbage(4096, 3));
        for (const char* name : {"1x1", "16384x1", "16385x1", "grey", "grey_alpha", "rgb16", "header_lies",
                                 "header_huge", "header_at_limit", "truncated", "empty", "garbage"})
            texturedModel(name, std::string(name) + ".png");
        // An uncompressed BMP header that claims 16384x16384 over 64 bytes of pixels (stb_image
        // would decode 1 GiB of zeros), and a progressive JPEG of 101 scans (each scan decodes the
        // whole image again; 5,000 of 14 bytes each take half a minute at 16384x16384).
        {
            std::string bmp = "BM";
            auto le = [&](uint32_t v, int n) {
                for (int i = 0; i < n; ++i) bmp += char((v >> (8 * i)) & 0xff);
            };
            le(0, 4), le(0, 4), le(54, 4);                               // file size, reserved, pixel offset
            le(40, 4), le(16384, 4), le(16384, 4), le(1, 2), le(32, 2);  // BITMAPINFOHEADER
            le(0, 4), le(0, 4), le(0, 4), le(0, 4), le(0, 4), le(0, 4);
            bmp += std::string(64, '\0');
            write("header_only.bmp", bmp);
            texturedModel("bmp", "header_only.bmp");
            auto segment = [](unsigned char marker, const std::string& payload) {
                return std::string("\xff", 1) + char(marker) + char((payload.size() + 2) >> 8) +
                       char((payload.size() + 2) & 0xff) + payload;
            };
            const std::string table = std::string(1, '\x01') + std::string(15, '\0');
            std::string jpeg = std::string("\xff\xd8", 2) +
                               segment(0xdb, std::string(1, '\0') + std::string(64, '\x01')) +
                               segment(0xc2, std::string("\x08\x00\x10\x00\x10\x01\x01\x11\x00", 9)) +
                               segment(0xc4, std::string(1, '\0') + table + std::string(1, '\0') +
                                                 std::string(1, '\x10') + table + std::string(1, '\xe0'));
            for (int scan = 0; scan < 101; ++scan)
                jpeg += segment(0xda, std::string("\x01\x01\x00\x01\x3f\x00", 6));
            jpeg += std::string("\xff\xd9", 2);
            write("scans.jpg", jpeg);
            texturedModel("scans", "scans.jpg");
        }
        // OBJ tags (tinyobjloader makes a megabyte of each for 20 characters), a hexadecimal
        // number (strtod reads 0x1p3 as 8, tinyobjloader as 0), and an mtllib line naming one
        // library 20,000 times (checked once, not 20,000 times).
        write("tags.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nt a 8192/8192/8192\nf 1 2 3\n");
        write("hex.obj", "v 0 0 0\nv 0x1p3 0 0\nv 0 1 0\nf 1 2 3\n");
        {
            std::string names, mtl = "newmtl m\n";
            for (int k = 0; k < 20000; ++k) names += " many.mtl";
            for (int k = 0; k < 5000; ++k) mtl += "Kd 1 1 1\n";
            write("many.mtl", mtl);
            write("mtllib_repeated.obj",
                  "mtllib" + names + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
        }
        // A Radiance HDR file with a truncated run (stb_image's reader would loop forever on it,
        // CVE-2021-42715), even named .png.
        write("loop.png",
              std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n\x02\x02\x00\x08", 49));
        texturedModel("hdr", "loop.png");

        // Scenes (all place tri.obj).
        write("scene_empty.json", "");
        write("scene_garbage.json", garbage(4096, 4));
        write("scene_utf16.json", utf16le(scene("")));
        write("scene_root_array.json", "[]\n");
        write("scene_models_object.json", R"({"models": {"file": "tri.obj"}})");
        write("scene_file_number.json", R"({"models": [{"file": 42}]})");
        write("scene_fov_string.json", scene(R"("camera": {"fov": "wide"})"));
        write("scene_lights_object.json", scene(R"("lights": {"type": "point"})"));
        write("scene_color_string.json",
              scene(R"("lights": [{"type": "point", "position": [0, 1, 0], "color": [1, "x", 1]}])"));
        write("scene_intensity_bool.json", scene(R"("ambient": {"intensity": true})"));
        write("scene_position_short.json", scene(R"("camera": {"position": [1, 2]})"));
        write("scene_marker_fraction.json",
              scene(R"("lights": [{"type": "point", "position": [0, 1, 0], "marker": 0.5}])"));
        write("scene_nan.json", scene(R"("ambient": {"intensity": NaN})"));
        write("scene_minus_inf.json", scene(R"("camera": {"position": [0, 0, -1e999]})"));
        write("scene_underflow_scale.json", R"({"models": [{"file": "tri.obj", "scale": 1e-999}]})");
        write("scene_negative_ambient.json", scene(R"("ambient": {"intensity": -0.5})"));
        write("scene_negative_color.json",
              scene(R"("lights": [{"type": "point", "position": [0, 1, 0], "color": [-1, 0, 0]}])"));
        write("scene_no_lights.json", scene(R"("lights": [])"));
        write(
            "scene_radiance_overflow.json",
            scene(
                R"("lights": [{"type": "point", "position": [0, 1, 0], "color": [1e20, 1, 1], "intensity": 1e20}])"));
        write("scene_ambient_overflow.json",
              scene(R"("ambient": {"color": [1, 1, 1e25], "intensity": 1e25})"));
        write("scene_deep.json",
              R"({"models": )" + std::string(100000, '[') + std::string(100000, ']') + "}");
        write("scene_lights_100000.json", manyLights(100000));
        write("scene_lights_100001.json", manyLights(100001));
        write("scene_models_100000.json", manyModels(100000));
        write("scene_models_100001.json", manyModels(100001));
        // A model of 11 meshes (one per material) placed 100,000 times: 1.1 million draws, past
        // the million a scene may make; refused at the 90,910th placement.
        std::string mtl, obj = "mtllib eleven.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
        for (int m = 0; m < 11; ++m) {
            mtl += "newmtl m" + std::to_string(m) + "\nKd 1 1 1\n";
            obj += "usemtl m" + std::to_string(m) + "\nf 1 2 3\n";
        }
        write("eleven.mtl", mtl);
        write("eleven.obj", obj);
        write("scene_draws_over.json", manyModels(100000, "eleven.obj"));

        // Not files at all, and a file too large to read: a directory, a named pipe (reading
        // one waits for a writer forever), and a sparse file of 3 GiB (no disk space used).
        fs::create_directories(gOut / "directory.obj");
        fs::remove(gOut / "fifo.obj");
        if (mkfifo((gOut / "fifo.obj").c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
        std::ofstream(gOut / "sparse_3gib.obj", std::ios::binary).put('v');
        fs::resize_file(gOut / "sparse_3gib.obj", uintmax_t{3} << 30);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "hostile_inputs: %s\n", error.what());
        return 1;
    }
    return 0;
}
