// doc_listings: keeps the code listings in docs/ identical to tagged regions of the sources.
//
// In a source file a region is marked with comment lines `//> name` ... `//< name` (names are
// unique per file; regions may nest, inner markers are left out of the outer listing). In a
// Markdown page a listing is a fenced block right after a marker line:
//
//   <!-- listing: chapter-06/main.cpp#load-meshes -->
//   ```cpp
//   ...the region, with its common indentation removed...
//   ```
//
//   doc_listings ROOT PAGE.md...            check: exit 1 naming every stale or missing listing
//   doc_listings --update ROOT PAGE.md...   rewrite the listings from the sources
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> readLines(const std::string& path, bool& ok) {
    std::ifstream in(path);
    ok = static_cast<bool>(in);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// The tag a line opens ('>') or closes ('<'), if it is a marker line.
std::optional<std::string> marker(const std::string& line, char kind) {
    std::string t = trim(line);
    std::string prefix = std::string("//") + kind + " ";
    if (t.rfind(prefix, 0) != 0) return std::nullopt;
    return trim(t.substr(prefix.size()));
}

bool isMarker(const std::string& line) {
    return marker(line, '>') || marker(line, '<');
}

// The region's lines with marker lines removed and the common indentation stripped.
std::optional<std::string> region(const std::vector<std::string>& lines, const std::string& tag,
                                  std::string& error) {
    std::optional<size_t> begin, end;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (marker(lines[i], '>') == tag) {
            if (begin) {
                error = "tag '" + tag + "' opens twice";
                return std::nullopt;
            }
            begin = i;
        } else if (marker(lines[i], '<') == tag && begin && !end) {
            end = i;
        }
    }
    if (!begin) {
        error = "tag '" + tag + "' not found";
        return std::nullopt;
    }
    if (!end) {
        error = "tag '" + tag + "' is never closed";
        return std::nullopt;
    }
    std::vector<std::string> body;
    for (size_t i = *begin + 1; i < *end; ++i)
        if (!isMarker(lines[i])) body.push_back(lines[i]);
    size_t indent = std::string::npos;
    for (const std::string& l : body)
        if (!trim(l).empty()) indent = std::min(indent, l.find_first_not_of(" \t"));
    std::string text;
    for (const std::string& l : body) text += (trim(l).empty() ? "" : l.substr(indent)) + "\n";
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    int first = 1;
    bool update = argc > 1 && std::string(argv[1]) == "--update";
    if (update) ++first;
    if (argc - first < 2) {
        std::cerr << "usage: doc_listings [--update] ROOT PAGE.md...\n";
        return 2;
    }
    std::string root = argv[first];
    int problems = 0, listings = 0;
    std::map<std::string, std::vector<std::string>> sources;
    for (int p = first + 1; p < argc; ++p) {
        std::string page = argv[p];
        bool ok = false;
        std::vector<std::string> lines = readLines(page, ok);
        if (!ok) {
            std::cerr << page << ": cannot read\n";
            ++problems;
            continue;
        }
        std::vector<std::string> out;
        bool changed = false;
        for (size_t i = 0; i < lines.size(); ++i) {
            out.push_back(lines[i]);
            std::string t = trim(lines[i]);
            const std::string open = "<!-- listing:";
            if (t.rfind(open, 0) != 0) continue;
            std::string spec = trim(t.substr(open.size(), t.size() - open.size() - 3));
            size_t hash = spec.find('#');
            std::string where = page + ":" + std::to_string(i + 1) + ": ";
            if (hash == std::string::npos || t.substr(t.size() - 3) != "-->") {
                std::cerr << where << "listing marker must read <!-- listing: FILE#TAG -->\n";
                ++problems;
                continue;
            }
            std::string file = spec.substr(0, hash), tag = spec.substr(hash + 1);
            ++listings;
            if (!sources.count(file)) {
                bool read = false;
                sources[file] = readLines(root + "/" + file, read);
                if (!read) sources[file].clear();
            }
            std::string error;
            std::optional<std::string> expected = region(sources[file], tag, error);
            if (!expected) {
                std::cerr << where << file << ": " << (sources[file].empty() ? "cannot read the file" : error)
                          << "\n";
                ++problems;
                continue;
            }
            // The fenced block that follows the marker.
            if (i + 1 >= lines.size() || trim(lines[i + 1]).rfind("```", 0) != 0) {
                std::cerr << where << "a ``` fenced block must follow the listing marker\n";
                ++problems;
                continue;
            }
            size_t close = i + 2;
            while (close < lines.size() && trim(lines[close]) != "```") ++close;
            if (close >= lines.size()) {
                std::cerr << where << "the fenced block is never closed\n";
                ++problems;
                continue;
            }
            std::string actual;
            for (size_t k = i + 2; k < close; ++k) actual += lines[k] + "\n";
            if (actual != *expected) {
                if (update) {
                    changed = true;
                } else {
                    std::cerr << where << "listing " << file << "#" << tag
                              << " is out of date (run: doc_listings --update, or cmake --build build "
                                 "--target update-docs)\n";
                    ++problems;
                }
            }
            out.push_back(lines[i + 1]);
            std::istringstream body(*expected);
            for (std::string l; std::getline(body, l);) out.push_back(l);
            out.push_back(lines[close]);
            i = close;
        }
        if (update && changed) {
            std::ofstream write(page, std::ios::trunc);
            for (const std::string& l : out) write << l << "\n";
            std::cout << "updated " << page << "\n";
        }
    }
    if (listings == 0) {
        std::cerr << "no listings found: the pages must pull their code from the sources\n";
        return 1;
    }
    std::cout << listings << " listings checked, " << problems << " problem(s)\n";
    return problems == 0 ? 0 : 1;
}
