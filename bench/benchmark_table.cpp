// benchmark_table frames REPORT.json...: one markdown table row per --benchmark --json report
// (median and p95 of the CPU and GPU frame, the median of each pass, startup, the command).
// benchmark_table bytes BANDWIDTH.json REPORT.json...: for chapter-15 reports, the bytes a G-buffer
// moves when written once and read once, the time that takes at the bandwidth `bandwidth` measured,
// and the measured scene + light passes beside it. bench/run.sh pastes both into docs/performance.md.
#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

nlohmann::json load(const char* path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(std::string("cannot open ") + path);
    return nlohmann::json::parse(in);
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof(text), pattern, value);
    return text;
}

std::string medianP95(const nlohmann::json& statistics) {
    return format("%.2f", statistics["median"].get<double>()) + " (" +
           format("%.2f", statistics["p95"].get<double>()) + ")";
}

// The command without its "--json PATH" (a temporary file of bench/run.sh).
std::string command(const nlohmann::json& r) {
    std::string text = r["command"];
    size_t json = text.find(" --json ");
    if (json == std::string::npos) return text;
    size_t next = text.find(' ', json + 8);
    return text.substr(0, json) + (next == std::string::npos ? "" : text.substr(next));
}

// The G-buffer layout, and the light pass's form when it is not the book's fragment shader.
std::string layout(const nlohmann::json& r) {
    std::string text = r.value("gbuffer", "-");
    if (r.value("light-pass", "fragment") != "fragment")
        text += ", " + r["light-pass"].get<std::string>() + " light";
    return text;
}

void frameRow(const nlohmann::json& r) {
    std::string passes, gpu = "no timestamps";
    if (r.value("gpu_timestamps", false)) {
        gpu = medianP95(r["gpu_ms"]["frame"]);
        // Passes in frame order (JSON objects do not keep it).
        for (const char* name : {"triangle", "geometry", "lighting", "scene", "light", "post"})
            if (r["gpu_ms"].contains(name))
                passes += (passes.empty() ? "" : ", ") + std::string(name) + " " +
                          format("%.2f", r["gpu_ms"][name]["median"].get<double>());
    }
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %.0f | `%s` |\n",
                r["chapter"].get<std::string>().c_str(), layout(r).c_str(),
                r["resolution"].get<std::string>().c_str(), r["present"].get<std::string>().c_str(),
                medianP95(r["cpu_frame_ms"]).c_str(), gpu.c_str(), passes.c_str(),
                r["startup_ms"].get<double>(), command(r).c_str());
}

void bytesRow(const nlohmann::json& r, double gbPerSecond) {
    if (!r.contains("gbuffer_bytes_per_pixel") || !r.value("gpu_timestamps", false)) return;
    std::string resolution = r["resolution"];
    double pixels = std::stod(resolution) * std::stod(resolution.substr(resolution.find('x') + 1));
    double bytesPerPixel = std::stod(r["gbuffer_bytes_per_pixel"].get<std::string>());
    double bytes = 2.0 * bytesPerPixel * pixels;  // written by the scene pass, read by the light pass
    double boundMs = bytes / (gbPerSecond * 1e9) * 1e3;
    const nlohmann::json& gpu = r["gpu_ms"];
    double measured = gpu["scene"]["median"].get<double>() + gpu["light"]["median"].get<double>();
    double sceneMs = gpu["scene"]["median"].get<double>();
    std::printf("| %s | %s | %.0f | %.1f | %.3f | %.3f | %.3f | %.1fx | %.1f |\n", layout(r).c_str(),
                resolution.c_str(), bytesPerPixel, bytes / 1e6, boundMs, sceneMs,
                gpu["light"]["median"].get<double>(), measured / boundMs,
                bytesPerPixel * pixels / (sceneMs * 1e-3) / 1e9);
}

}  // namespace

int main(int argc, char** argv) {
    std::string mode = argc > 1 ? argv[1] : "";
    if (argc < 3 || (mode != "frames" && mode != "bytes") || (mode == "bytes" && argc < 4)) {
        std::fprintf(stderr,
                     "usage: benchmark_table frames REPORT.json...\n"
                     "       benchmark_table bytes BANDWIDTH.json REPORT.json...\n");
        return 2;
    }
    try {
        if (mode == "frames") {
            std::printf(
                "| chapter | G-buffer | resolution | present | CPU frame ms, median (p95) "
                "| GPU frame ms, median (p95) | GPU per pass ms, median | startup ms | command |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
            for (int i = 2; i < argc; ++i) frameRow(load(argv[i]));
        } else {
            double gbPerSecond = load(argv[2])["bandwidth_gb_per_s"].get<double>();
            std::printf(
                "| G-buffer | resolution | B/px | MB moved | at %.0f GB/s, ms | scene ms | light ms "
                "| (scene + light) / bandwidth time | G-buffer bytes / scene time, GB/s |\n"
                "|---|---|---|---|---|---|---|---|---|\n",
                gbPerSecond);
            for (int i = 3; i < argc; ++i) bytesRow(load(argv[i]), gbPerSecond);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "benchmark_table: %s\n", error.what());
        return 1;
    }
    return 0;
}
