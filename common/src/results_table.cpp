#include "rasterlab/results_table.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "rasterlab/file_io.hpp"

namespace rl {
namespace {

std::string format_value(const ResultsTable::Value& value) {
    if (const auto* text = std::get_if<std::string>(&value)) return *text;
    if (const auto* whole = std::get_if<long long>(&value)) return std::to_string(*whole);
    const double real = std::get<double>(value);
    if (std::isnan(real)) return "nan";
    if (std::isinf(real)) return real > 0 ? "inf" : "-inf";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", real);  // round-trips a float exactly
    return buffer;
}

std::string quoted_if_needed(const std::string& field) {
    if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
    std::string out = "\"";
    for (char c : field) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + '"';
}

void append_row(std::string& out, const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i) out += ',';
        out += quoted_if_needed(fields[i]);
    }
    out += '\n';
}

}  // namespace

ResultsTable::ResultsTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
    if (columns_.empty()) throw std::invalid_argument("a results table needs columns");
}

void ResultsTable::add_row(std::initializer_list<Value> values) {
    if (values.size() != columns_.size())
        throw std::invalid_argument("row of " + std::to_string(values.size()) +
                                    " values for a table of " + std::to_string(columns_.size()) +
                                    " columns");
    std::vector<std::string> row;
    for (const Value& v : values) row.push_back(format_value(v));
    rows_.push_back(std::move(row));
}

std::string ResultsTable::to_csv() const {
    std::string out;
    append_row(out, columns_);
    for (const auto& row : rows_) append_row(out, row);
    return out;
}

void ResultsTable::write_csv(const std::filesystem::path& path) const {
    const std::string csv = to_csv();
    write_file_atomically(path,
                          std::span(reinterpret_cast<const std::uint8_t*>(csv.data()), csv.size()));
}

}  // namespace rl
