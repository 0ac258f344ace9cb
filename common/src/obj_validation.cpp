#include "obj_validation.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "rasterlab/mesh.hpp"

namespace rl {
namespace {

constexpr std::string_view kBlank = " \t\r\v\f";

// 'text', for messages. (Built by appending: GCC 12 warns falsely about
// "literal" + std::string here.)
std::string quoted(std::string_view text) {
    std::string out;
    out += '\'';
    out += text;
    out += '\'';
    return out;
}

std::vector<std::string_view> tokens_of(std::string_view line) {
    std::vector<std::string_view> tokens;
    for (std::size_t at = line.find_first_not_of(kBlank); at != std::string_view::npos;) {
        const std::size_t end = std::min(line.find_first_of(kBlank, at), line.size());
        tokens.push_back(line.substr(at, end - at));
        at = line.find_first_not_of(kBlank, end);
    }
    return tokens;
}

// The three kinds of data a face corner refers to, with how many of each the
// file defines so far and in all.
struct Kind {
    const char* name;  // as in messages: "vertex", "texture coordinate", "normal"
    std::int64_t so_far = 0, total = 0;
};

class Validator {
  public:
    Validator(std::string_view text, const std::string& name) : text_(text), name_(name) {}

    void run() {
        // Pass 1 counts each kind, so that a positive index can be checked
        // against the file's total (OBJ allows referring to later vertices).
        for_each_line([&](const std::vector<std::string_view>& t) {
            if (Kind* kind = kind_of(t[0])) ++kind->total;
        });
        for_each_line([&](const std::vector<std::string_view>& t) {
            if (Kind* kind = kind_of(t[0])) {
                check_numbers(t, t[0] == "vt" ? 1u : 3u);
                ++kind->so_far;
            } else if (t[0] == "f") {
                check_face(t);
            }
        });
    }

  private:
    template <class Visit>
    void for_each_line(Visit&& visit) {
        line_ = 0;
        for (std::size_t start = 0; start <= text_.size();) {
            const std::size_t end = std::min(text_.find('\n', start), text_.size());
            std::string_view line = text_.substr(start, end - start);
            ++line_;
            line = line.substr(0, line.find('#'));
            const std::vector<std::string_view> t = tokens_of(line);
            if (!t.empty()) visit(t);
            start = end + 1;
        }
    }

    Kind* kind_of(std::string_view keyword) {
        if (keyword == "v") return &positions_;
        if (keyword == "vt") return &uvs_;
        if (keyword == "vn") return &normals_;
        return nullptr;
    }

    [[noreturn]] void fail(const std::string& problem) const {
        throw MeshError(name_, "line " + std::to_string(line_) + ": " + problem);
    }

    // Every number is finite and within float's range: tinyobjloader would
    // read "nan" and "inf" as 0, "1e400" as infinity, and garbage as 0.
    void check_numbers(const std::vector<std::string_view>& t, std::size_t at_least) {
        if (t.size() - 1 < at_least)
            fail(quoted(t[0]) + " needs " + std::to_string(at_least) + " numbers");
        for (std::size_t i = 1; i < t.size(); ++i) {
            std::string_view s = t[i];
            if (s.starts_with('+')) s.remove_prefix(1);
            double value = 0;
            const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
            if (error == std::errc::result_out_of_range ||
                (error == std::errc{} && std::isfinite(value) &&
                 std::abs(value) > std::numeric_limits<float>::max()))
                fail(quoted(t[i]) + " is beyond the range of a float");
            if (error != std::errc{} || end != s.data() + s.size())
                fail(quoted(t[i]) + " is not a number");
            if (!std::isfinite(value)) fail(quoted(t[i]) + " is not a finite number");
        }
    }

    // One component of a face corner: a non-zero integer, counted from 1, or
    // back from the latest definition when negative.
    void check_index(std::string_view s, Kind& kind) {
        const bool negative = s.starts_with('-');
        const std::string_view digits = negative ? s.substr(1) : s;
        std::int64_t value = 0;
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (digits.empty() || error == std::errc::invalid_argument ||
            end != digits.data() + digits.size())
            fail(std::string(kind.name) + " index " + quoted(s) + " is not an integer");
        const std::int64_t limit = negative ? kind.so_far : kind.total;
        if (error == std::errc::result_out_of_range || value == 0 || value > limit)
            fail(std::string(kind.name) + " index " + std::string(s) + " is out of range (" +
                 (negative ? "the file defines " + std::to_string(limit) + " before this line"
                           : "the file defines " + std::to_string(limit)) +
                 ")");
    }

    void check_face(const std::vector<std::string_view>& t) {
        const std::size_t corners = t.size() - 1;
        if (corners < 3)
            fail("a face with " + std::to_string(corners) +
                 " vertices (faces need three or more valid vertex indices)");
        if (corners > kMaxFaceVertices)
            fail("a face with " + std::to_string(corners) + " vertices, more than the " +
                 std::to_string(kMaxFaceVertices) + " a face may have here");
        for (std::size_t i = 1; i < t.size(); ++i) {
            Kind* kinds[3] = {&positions_, &uvs_, &normals_};
            std::string_view rest = t[i];
            for (int part = 0; part < 3; ++part) {
                const std::size_t slash = rest.find('/');
                const std::string_view component = rest.substr(0, slash);
                if (!component.empty() || part == 0) check_index(component, *kinds[part]);
                if (slash == std::string_view::npos) break;
                rest.remove_prefix(slash + 1);
                if (part == 2) fail("face corner " + quoted(t[i]) + " has extra parts");
            }
        }
    }

    std::string_view text_;
    const std::string& name_;
    std::size_t line_ = 0;
    Kind positions_{"vertex"}, uvs_{"texture coordinate"}, normals_{"normal"};
};

}  // namespace

void validate_obj_text(std::string_view text, const std::string& name) {
    Validator(text, name).run();
}

}  // namespace rl
