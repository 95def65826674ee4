// image_compare: checks a rendered PNG -- its size, chosen pixels, and its match to a golden
// image within a per-channel tolerance on a bounded fraction of pixels (the Filament scheme:
// at most --max-fraction of pixels may differ by more than --max-diff in any channel).
//
//   image_compare IMAGE [--size W H] [--pixel-linear X Y R G B]... [--pixel X Y R G B]...
//                       [--pixel-tolerance N] [--golden FILE --max-diff N --max-fraction F]
//                       [--expect-scaled REFERENCE FACTOR --max-diff N --max-fraction F]
//                       [--overlay-like BASE OTHER OTHER_BASE] [--mirrored]
//
// --pixel-linear takes a linear colour (what a shader writes or a clear colour holds) and
// expects its sRGB encoding in the PNG; --pixel takes 8-bit values as stored. --expect-scaled
// checks IMAGE = FACTOR x REFERENCE in linear colour (both PNGs sRGB-encoded), with the same
// per-channel tolerance. On a golden mismatch an image of the differing pixels is written to
// IMAGE.diff.png.
// --overlay-like checks that an overlay covers the same part of the window in two images of
// different sizes (a HiDPI scale against scale 1): IMAGE minus BASE (the same run without the
// overlay) is where IMAGE's overlay is; OTHER minus OTHER_BASE is the other's. Both masks are taken
// to the smaller size (a pixel is covered when most of its block is); they must overlap by at least
// 95% (intersection over union) and their bounding boxes agree within 1% of the width and height.
#include <stb_image.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct Png {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

bool load(const char* path, Png& png) {
    int channels = 0;
    unsigned char* data = stbi_load(path, &png.width, &png.height, &channels, 3);
    if (!data) {
        std::fprintf(stderr, "image_compare: cannot read '%s': %s\n", path, stbi_failure_reason());
        return false;
    }
    png.rgb.assign(data, data + size_t(png.width) * png.height * 3);
    stbi_image_free(data);
    return true;
}

double decodeSrgb(int encoded) {
    double c = encoded / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The sRGB transfer function (IEC 61966-2-1), rounded to 8 bits.
int encodeSrgb(double linear) {
    double c = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(std::fmin(std::fmax(c, 0.0), 1.0) * 255.0));
}

// Where `gui` differs from `base` (any channel by more than 16), at `size`x`size` blocks.
std::vector<bool> overlayMask(const Png& gui, const Png& base, int block, int width, int height) {
    std::vector<bool> mask(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            int covered = 0;
            for (int by = 0; by < block; ++by)
                for (int bx = 0; bx < block; ++bx) {
                    size_t i = (size_t(y * block + by) * gui.width + size_t(x * block + bx)) * 3;
                    bool differs = false;
                    for (int c = 0; c < 3; ++c)
                        differs = differs || std::abs(gui.rgb[i + c] - base.rgb[i + c]) > 16;
                    covered += differs;
                }
            mask[size_t(y) * width + x] = covered * 2 > block * block;
        }
    return mask;
}

struct PixelCheck {
    int x, y, rgb[3];
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: image_compare IMAGE [options] (see the source)\n");
        return 2;
    }
    const char* imagePath = argv[1];
    int wantWidth = -1, wantHeight = -1, pixelTolerance = 2, maxDiff = 5;
    double maxFraction = 0.001;
    const char* golden = nullptr;
    const char* scaledReference = nullptr;
    double scale = 1.0;
    std::vector<PixelCheck> pixels;
    const char* overlayBase = nullptr;
    const char* overlayOther = nullptr;
    const char* overlayOtherBase = nullptr;
    bool mirrored = false;  // --mirrored: the golden is compared with its mirror image (left <-> right)
    for (int i = 2; i < argc; ++i) {
        std::string_view arg = argv[i];
        auto need = [&](int n) {
            if (i + n >= argc) {
                std::fprintf(stderr, "image_compare: %s needs %d values\n", argv[i], n);
                std::exit(2);
            }
        };
        if (arg == "--size") {
            need(2);
            wantWidth = std::atoi(argv[++i]);
            wantHeight = std::atoi(argv[++i]);
        } else if (arg == "--pixel" || arg == "--pixel-linear") {
            need(5);
            PixelCheck p{std::atoi(argv[i + 1]), std::atoi(argv[i + 2]), {}};
            for (int c = 0; c < 3; ++c)
                p.rgb[c] =
                    arg == "--pixel" ? std::atoi(argv[i + 3 + c]) : encodeSrgb(std::atof(argv[i + 3 + c]));
            pixels.push_back(p);
            i += 5;
        } else if (arg == "--pixel-tolerance") {
            need(1);
            pixelTolerance = std::atoi(argv[++i]);
        } else if (arg == "--golden") {
            need(1);
            golden = argv[++i];
        } else if (arg == "--expect-scaled") {
            need(2);
            scaledReference = argv[++i];
            scale = std::atof(argv[++i]);
        } else if (arg == "--overlay-like") {
            need(3);
            overlayBase = argv[++i];
            overlayOther = argv[++i];
            overlayOtherBase = argv[++i];
        } else if (arg == "--mirrored") {
            mirrored = true;
        } else if (arg == "--max-diff") {
            need(1);
            maxDiff = std::atoi(argv[++i]);
        } else if (arg == "--max-fraction") {
            need(1);
            maxFraction = std::atof(argv[++i]);
        } else {
            std::fprintf(stderr, "image_compare: unknown option '%s'\n", argv[i]);
            return 2;
        }
    }

    Png image;
    if (!load(imagePath, image)) return 1;
    int failures = 0;
    if (wantWidth >= 0 && (image.width != wantWidth || image.height != wantHeight)) {
        std::printf("FAIL size: %dx%d, expected %dx%d\n", image.width, image.height, wantWidth, wantHeight);
        return 1;  // nothing else can be compared meaningfully
    }
    for (const PixelCheck& p : pixels) {
        if (p.x < 0 || p.y < 0 || p.x >= image.width || p.y >= image.height) {
            std::printf("FAIL pixel (%d,%d) is outside the image\n", p.x, p.y);
            ++failures;
            continue;
        }
        const unsigned char* got = &image.rgb[(size_t(p.y) * image.width + p.x) * 3];
        bool ok = true;
        for (int c = 0; c < 3; ++c) ok = ok && std::abs(got[c] - p.rgb[c]) <= pixelTolerance;
        std::printf("%s pixel (%d,%d): (%d,%d,%d), expected (%d,%d,%d) +-%d\n", ok ? "ok  " : "FAIL", p.x,
                    p.y, got[0], got[1], got[2], p.rgb[0], p.rgb[1], p.rgb[2], pixelTolerance);
        failures += !ok;
    }

    if (golden) {
        Png reference;
        if (!load(golden, reference)) return 1;
        if (reference.width != image.width || reference.height != image.height) {
            std::printf("FAIL golden is %dx%d, image is %dx%d\n", reference.width, reference.height,
                        image.width, image.height);
            return 1;
        }
        if (mirrored)
            for (int y = 0; y < reference.height; ++y)
                for (int x = 0; x < reference.width / 2; ++x)
                    for (int c = 0; c < 3; ++c)
                        std::swap(
                            reference.rgb[(size_t(y) * reference.width + size_t(x)) * 3 + size_t(c)],
                            reference
                                .rgb[(size_t(y) * reference.width + size_t(reference.width - 1 - x)) * 3 +
                                     size_t(c)]);
        size_t count = size_t(image.width) * image.height, over = 0;
        int worst = 0;
        double sumSquares = 0;
        std::vector<unsigned char> diff(count * 3, 0);
        for (size_t i = 0; i < count; ++i) {
            int pixelWorst = 0;
            for (int c = 0; c < 3; ++c) {
                int d = std::abs(image.rgb[i * 3 + c] - reference.rgb[i * 3 + c]);
                pixelWorst = std::max(pixelWorst, d);
                sumSquares += double(d) * d;
            }
            worst = std::max(worst, pixelWorst);
            if (pixelWorst > maxDiff) {
                ++over;
                diff[i * 3] = 255;
            } else if (pixelWorst > 0) {
                diff[i * 3 + 1] = 255;
            }
        }
        double fraction = double(over) / double(count);
        double rmse = std::sqrt(sumSquares / double(count * 3));
        bool ok = fraction <= maxFraction;
        std::printf(
            "%s golden %s: max abs diff %d/255, RMSE %.4f/255, %zu pixels (%.5f%%) over %d/255, "
            "allowed %.5f%%\n",
            ok ? "ok  " : "FAIL", golden, worst, rmse, over, fraction * 100.0, maxDiff, maxFraction * 100.0);
        if (!ok) {
            std::string diffPath = std::string(imagePath) + ".diff.png";
            stbi_write_png(diffPath.c_str(), image.width, image.height, 3, diff.data(), image.width * 3);
            std::printf("     differing pixels (red: over the tolerance, green: under it): %s\n",
                        diffPath.c_str());
            ++failures;
        }
    }
    if (overlayBase) {
        Png base, other, otherBase;
        if (!load(overlayBase, base) || !load(overlayOther, other) || !load(overlayOtherBase, otherBase))
            return 1;
        const Png& small = other.width < image.width ? other : image;
        const Png& large = other.width < image.width ? image : other;
        const Png& smallBase = other.width < image.width ? otherBase : base;
        const Png& largeBase = other.width < image.width ? base : otherBase;
        int block = large.width / small.width;
        if (base.width != image.width || otherBase.width != other.width || block < 1 ||
            large.width != small.width * block || large.height != small.height * block) {
            std::printf("FAIL --overlay-like: sizes %dx%d and %dx%d are not a whole multiple of each other\n",
                        image.width, image.height, other.width, other.height);
            return 1;
        }
        int w = small.width, h = small.height;
        std::vector<bool> a = overlayMask(small, smallBase, 1, w, h),
                          b = overlayMask(large, largeBase, block, w, h);
        size_t both = 0, either = 0;
        int box[2][4] = {{w, h, -1, -1}, {w, h, -1, -1}};  // x0, y0, x1, y1
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                bool in[2] = {a[size_t(y) * w + x], b[size_t(y) * w + x]};
                both += in[0] && in[1];
                either += in[0] || in[1];
                for (int m = 0; m < 2; ++m)
                    if (in[m]) {
                        box[m][0] = std::min(box[m][0], x), box[m][1] = std::min(box[m][1], y);
                        box[m][2] = std::max(box[m][2], x), box[m][3] = std::max(box[m][3], y);
                    }
            }
        double iou = either ? double(both) / double(either) : 0.0;
        int worstEdge = 0;
        for (int e = 0; e < 4; ++e) worstEdge = std::max(worstEdge, std::abs(box[0][e] - box[1][e]));
        bool ok = either > 0 && iou >= 0.95 && worstEdge <= std::max(w, h) / 100;
        std::printf(
            "%s overlay: %zu pixels at %dx%d, intersection over union %.4f (at least 0.95), bounding boxes "
            "(%d,%d)-(%d,%d) and (%d,%d)-(%d,%d), edges %d pixels apart (at most %d)\n",
            ok ? "ok  " : "FAIL", either, w, h, iou, box[0][0], box[0][1], box[0][2], box[0][3], box[1][0],
            box[1][1], box[1][2], box[1][3], worstEdge, std::max(w, h) / 100);
        failures += !ok;
    }
    if (scaledReference) {
        Png reference;
        if (!load(scaledReference, reference)) return 1;
        if (reference.width != image.width || reference.height != image.height) {
            std::printf("FAIL %s is %dx%d, image is %dx%d\n", scaledReference, reference.width,
                        reference.height, image.width, image.height);
            return 1;
        }
        size_t over = 0, count = reference.rgb.size();
        int worst = 0;
        for (size_t i = 0; i < count; ++i) {
            int expected = encodeSrgb(scale * decodeSrgb(reference.rgb[i]));
            int d = std::abs(int(image.rgb[i]) - expected);
            worst = std::max(worst, d);
            over += d > maxDiff;
        }
        double fraction = double(over) / double(count);
        bool ok = fraction <= maxFraction;
        std::printf(
            "%s image = %g x %s (linear): max abs diff %d/255, %zu channels (%.5f%%) over %d/255, "
            "allowed %.5f%%\n",
            ok ? "ok  " : "FAIL", scale, scaledReference, worst, over, fraction * 100.0, maxDiff,
            maxFraction * 100.0);
        failures += !ok;
    }
    return failures == 0 ? 0 : 1;
}
