// pfm_compare A.pfm B.pfm --lights N [--min-lit F]
//
// Checks that two light outputs of chapter-15 (--dump's light.pfm) are the same image up to fp32
// rounding of the sum over lights: the test of light culling, whose image must equal the book's
// loop over every light when the lights have the same ranges. The two sum the same light terms
// (zero for a light out of range) in different orders, so by the usual bound for a sum of n
// non-negative terms (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., eq. 4.4)
// each is within (n - 1) u of the exact sum, u = 2^-24; and each term may itself round
// differently in the two shader variants (another instruction order), by a few u. So every value
// must satisfy |a - b| <= (2 (n - 1) + 16) u max(|a|, |b|), n the scene's light count (every
// light may reach a pixel), plus 1e-30 for values that underflow. --min-lit F: at least this
// fraction of values must be positive, so that two black images do not pass as a match.
// Exit 0 when every value holds; prints the worst one.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Pfm {
    int width = 0, height = 0, channels = 0;
    std::vector<float> values;
};

bool readPfm(const char* path, Pfm& pfm) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    double scale = 0;
    in >> magic >> pfm.width >> pfm.height >> scale;
    in.get();
    if (!in || (magic != "PF" && magic != "Pf") || scale >= 0 || pfm.width <= 0 || pfm.height <= 0)
        return false;
    pfm.channels = magic == "PF" ? 3 : 1;
    pfm.values.resize(size_t(pfm.width) * size_t(pfm.height) * size_t(pfm.channels));
    in.read(reinterpret_cast<char*>(pfm.values.data()), std::streamsize(pfm.values.size() * sizeof(float)));
    return bool(in);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5 || std::strcmp(argv[3], "--lights") != 0) {
        std::fprintf(stderr, "usage: pfm_compare A.pfm B.pfm --lights N [--min-lit F]\n");
        return 2;
    }
    double lights = std::atof(argv[4]);
    double minLit = argc >= 7 && std::strcmp(argv[5], "--min-lit") == 0 ? std::atof(argv[6]) : 0.0;
    Pfm a, b;
    if (!readPfm(argv[1], a) || !readPfm(argv[2], b)) {
        std::fprintf(stderr, "pfm_compare: cannot read %s or %s as PFM\n", argv[1], argv[2]);
        return 2;
    }
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        std::fprintf(stderr, "pfm_compare: %dx%d against %dx%d\n", a.width, a.height, b.width, b.height);
        return 1;
    }
    const double u = std::ldexp(1.0, -24);
    const double relative = (2.0 * std::max(lights - 1.0, 0.0) + 16.0) * u;
    size_t failures = 0, lit = 0, worst = 0;
    double worstRatio = 0.0;
    for (size_t i = 0; i < a.values.size(); ++i) {
        double x = a.values[i], y = b.values[i];
        if (!std::isfinite(x) || !std::isfinite(y)) {
            ++failures;
            continue;
        }
        lit += x > 0.0 ? 1 : 0;
        double bound = relative * std::max(std::fabs(x), std::fabs(y)) + 1e-30;
        double ratio = std::fabs(x - y) / bound;
        if (ratio > worstRatio) worstRatio = ratio, worst = i;
        failures += ratio > 1.0 ? 1 : 0;
    }
    size_t pixel = worst / size_t(a.channels);
    double litFraction = double(lit) / double(a.values.size());
    std::printf(
        "pfm_compare: %zu values, %.1f%% lit; worst at pixel (%zu, %zu): %.9g against %.9g, %.3g of the "
        "bound (%.3g relative, %g lights); %zu values beyond it\n",
        a.values.size(), litFraction * 100.0, pixel % size_t(a.width), pixel / size_t(a.width),
        double(a.values[worst]), double(b.values[worst]), worstRatio, relative, lights, failures);
    if (litFraction < minLit) {
        std::printf("pfm_compare: only %.1f%% of the values are lit, fewer than --min-lit %g\n",
                    litFraction * 100.0, minLit);
        return 1;
    }
    return failures == 0 ? 0 : 1;
}
