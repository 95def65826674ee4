// benchmark_check REPORT.json PASS...: checks a --benchmark --json report: it parses, holds every
// field, counts the frames asked for, and on every frame each pass's GPU time is positive and the
// passes add up to no more than the frame's GPU time. Exit 0 when all hold; each problem is printed.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: benchmark_check REPORT.json MEASURED_FRAMES PASS...\n");
        return 2;
    }
    int problems = 0;
    auto problem = [&](const std::string& what) {
        std::printf("FAIL %s\n", what.c_str());
        ++problems;
    };
    nlohmann::json report;
    try {
        std::ifstream in(argv[1]);
        report = nlohmann::json::parse(in);
    } catch (const std::exception& error) {
        std::printf("FAIL %s does not parse: %s\n", argv[1], error.what());
        return 1;
    }
    size_t frames = std::stoul(argv[2]);
    std::vector<std::string> passes(argv + 3, argv + argc);

    for (const char* key :
         {"chapter", "device", "driver", "resolution", "frames_in_flight", "present", "command"})
        if (!report.contains(key) || !report[key].is_string())
            problem(std::string("no string field '") + key + "'");
    for (const char* key : {"measured_frames", "warmup_frames", "startup_ms"})
        if (!report.contains(key) || !report[key].is_number())
            problem(std::string("no number field '") + key + "'");
    if (report.value("measured_frames", 0u) != frames)
        problem("measured_frames is not " + std::to_string(frames));
    if (!(report.value("startup_ms", 0.0) > 0.0)) problem("startup_ms is not positive");

    auto statistics = [&](const nlohmann::json& s, const std::string& name) -> std::vector<double> {
        for (const char* key : {"median", "p95", "min", "max"})
            if (!s.contains(key) || !s[key].is_number()) problem(name + " has no number '" + key + "'");
        if (!s.contains("frames") || !s["frames"].is_array() || s["frames"].size() != frames) {
            problem(name + " does not list " + std::to_string(frames) + " frames");
            return {};
        }
        if (!(s["min"].get<double>() <= s["median"].get<double>() &&
              s["median"].get<double>() <= s["p95"].get<double>() &&
              s["p95"].get<double>() <= s["max"].get<double>()))
            problem(name + ": not min <= median <= p95 <= max");
        return s["frames"].get<std::vector<double>>();
    };
    if (!report.contains("cpu_frame_ms"))
        problem("no cpu_frame_ms");
    else
        statistics(report["cpu_frame_ms"], "cpu_frame_ms");

    if (!report.value("gpu_timestamps", false)) {
        problem("gpu_timestamps is not true (the device here has timestamps)");
    } else if (!report.contains("gpu_ms") || !report["gpu_ms"].contains("frame")) {
        problem("no gpu_ms.frame");
    } else {
        std::vector<double> frame = statistics(report["gpu_ms"]["frame"], "gpu_ms.frame");
        std::vector<double> sum(frame.size(), 0.0);
        for (const std::string& pass : passes) {
            if (!report["gpu_ms"].contains(pass)) {
                problem("no gpu_ms." + pass);
                continue;
            }
            std::vector<double> times = statistics(report["gpu_ms"][pass], "gpu_ms." + pass);
            for (size_t i = 0; i < times.size() && i < sum.size(); ++i) {
                if (!(times[i] > 0.0))
                    problem("gpu_ms." + pass + " frame " + std::to_string(i) + " is not positive");
                sum[i] += times[i];
            }
        }
        for (size_t i = 0; i < frame.size(); ++i)
            if (sum[i] > frame[i] * (1.0 + 1e-9) + 1e-9)
                problem("frame " + std::to_string(i) + ": the passes take " + std::to_string(sum[i]) +
                        " ms, more than the frame's " + std::to_string(frame[i]) + " ms");
    }
    std::printf("%s: %d problem(s)\n", argv[1], problems);
    return problems == 0 ? 0 : 1;
}
