// A small table of lab results, written as CSV: one header row, then one row
// per measurement. Values are kept as text exactly as added.
//
//   rl::ResultsTable table({"method", "scene", "ns_per_triangle", "triangles"});
//   table.add_row({"edge", "small (10 px)", 12.5, 20000LL});  // text, double or long long
//   table.write_csv(options.out_dir / "02_triangles_coverage.csv");
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

namespace rl {

class ResultsTable {
  public:
    using Value = std::variant<std::string, long long, double>;

    explicit ResultsTable(std::vector<std::string> columns);

    // Throws std::invalid_argument unless the row has one value per column.
    void add_row(std::initializer_list<Value> values);

    // RFC 4180 CSV: fields with commas, quotes or newlines are quoted.
    std::string to_csv() const;
    void write_csv(const std::filesystem::path& path) const;  // atomically

  private:
    std::vector<std::string> columns_;
    std::vector<std::vector<std::string>> rows_;
};

}  // namespace rl
