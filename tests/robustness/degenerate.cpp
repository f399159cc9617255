#include "robustness/degenerate.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace cg::test {

namespace {

std::string read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot open " + path);
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

std::string escape_pointer_token(const std::string& key) {
    std::string out;
    for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return out;
}

void collect(const json& j, const std::string& pointer, const std::string& path,
             std::vector<Leaf>& out) {
    if (j.is_number()) {
        out.push_back({pointer, path});
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i)
            collect(j[i], pointer + "/" + std::to_string(i), path + "[" + std::to_string(i) + "]", out);
    } else if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            collect(it.value(), pointer + "/" + escape_pointer_token(it.key()),
                    path + (path.empty() ? "" : ".") + it.key(), out);
    }
}

std::string marker(std::size_t k) { return "@@robustness-raw-" + std::to_string(k) + "@@"; }

}  // namespace

std::vector<Table> load_tables() {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(CG_SOURCE_DIR "/tests/robustness/tables"))
        if (e.path().extension() == ".json") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    std::vector<Table> tables;
    for (const std::string& f : files) {
        json j = json::parse(read_file(f));
        tables.push_back({j.value("algorithm", ""), f, j.value("base", json()), j.value("rows", json::array())});
    }
    return tables;
}

std::string row_text(const json& base, const json& row) {
    if (row.contains("text")) return row["text"].get<std::string>();
    json in = row.contains("input") ? row["input"] : base;
    if (row.contains("set"))
        for (auto it = row["set"].begin(); it != row["set"].end(); ++it)
            in[json::json_pointer(it.key())] = it.value();
    if (row.contains("remove"))
        for (const auto& p : row["remove"]) {
            json::json_pointer ptr(p.get<std::string>());
            json& parent = in.at(ptr.parent_pointer());
            if (parent.is_object()) parent.erase(ptr.back());
            else parent.erase(std::stoul(ptr.back()));
        }
    std::vector<std::string> raws;
    if (row.contains("raw"))
        for (auto it = row["raw"].begin(); it != row["raw"].end(); ++it) {
            in[json::json_pointer(it.key())] = marker(raws.size());
            raws.push_back(it.value().get<std::string>());
        }
    std::string text = in.dump();
    for (std::size_t k = 0; k < raws.size(); ++k) {
        const std::string m = "\"" + marker(k) + "\"";
        text.replace(text.find(m), m.size(), raws[k]);
    }
    return text;
}

std::vector<Leaf> numeric_leaves(const json& j) {
    std::vector<Leaf> out;
    collect(j, "", "", out);
    return out;
}

std::string splice_raw(const json& j, const std::string& pointer, const std::string& raw) {
    json copy = j;
    copy[json::json_pointer(pointer)] = marker(0);
    std::string text = copy.dump();
    const std::string m = "\"" + marker(0) + "\"";
    return text.replace(text.find(m), m.size(), raw);
}

bool matches(const json& expected, const json& actual, std::string& why) {
    if (expected.is_number() && actual.is_number()) {
        const double e = expected.get<double>(), a = actual.get<double>();
        if (std::fabs(a - e) <= 1e-12 + 1e-9 * std::fabs(e)) return true;
        why = "expected " + expected.dump() + ", got " + actual.dump();
        return false;
    }
    if (expected.is_object()) {
        if (!actual.is_object()) return why = "expected an object, got " + actual.dump(), false;
        for (auto it = expected.begin(); it != expected.end(); ++it) {
            if (!actual.contains(it.key())) return why = it.key() + ": missing", false;
            if (!matches(it.value(), actual[it.key()], why)) return why = it.key() + ": " + why, false;
        }
        return true;
    }
    if (expected.is_array()) {
        if (!actual.is_array() || actual.size() != expected.size())
            return why = "expected " + expected.dump() + ", got " + actual.dump(), false;
        for (std::size_t i = 0; i < expected.size(); ++i)
            if (!matches(expected[i], actual[i], why))
                return why = "[" + std::to_string(i) + "]: " + why, false;
        return true;
    }
    if (expected == actual) return true;
    why = "expected " + expected.dump() + ", got " + actual.dump();
    return false;
}

std::vector<std::string> non_finite(const json& j, const std::string& path) {
    std::vector<std::string> out;
    if (j.is_number_float() && !std::isfinite(j.get<double>())) out.push_back(path);
    if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i) {
            auto sub = non_finite(j[i], path + "[" + std::to_string(i) + "]");
            out.insert(out.end(), sub.begin(), sub.end());
        }
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it) {
            auto sub = non_finite(it.value(), path + "." + it.key());
            out.insert(out.end(), sub.begin(), sub.end());
        }
    return out;
}

}  // namespace cg::test
