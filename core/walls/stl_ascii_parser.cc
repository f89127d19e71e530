#include "core/walls/stl_ascii_parser.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace demcal::core {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool IEquals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsSpace(s.back())) s.remove_suffix(1);
  return s;
}

// Shows a token in a message (bounded length, never empty).
std::string Quote(std::string_view token) {
  if (token.empty()) return "the end of the file";
  std::string q(1, '\'');
  q.append(token.substr(0, 40));
  q.append(token.size() > 40 ? "...'" : "'");
  return q;
}

// Whitespace-separated tokens with line numbers.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {}

  // The next token, or "" at the end of the text.
  std::string_view Next() {
    while (pos_ < text_.size() && IsSpace(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const size_t start = pos_;
    while (pos_ < text_.size() && !IsSpace(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  // The rest of the current line (the newline is left for Next to count).
  std::string_view RestOfLine() {
    const size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }

  int line() const { return line_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int line_ = 1;
};

class Parser {
 public:
  Parser(std::string_view text, std::string* error) : cursor_(text), error_(error) {}

  MeshIoStatus Run(std::vector<StlTriangle>* triangles, std::string* name,
                   std::vector<std::string>* /*warnings: none raised yet*/) {
    cursor_.Next();  // "solid", checked by the caller
    *name = std::string(Trim(cursor_.RestOfLine()));
    bool in_solid = true;
    while (true) {
      const std::string_view token = cursor_.Next();
      if (token.empty()) {
        // A file cut short after a whole facet parses cleanly; only the missing 'endsolid'
        // tells, and half a mesh must not run silently.
        if (in_solid)
          Fail(MeshIoStatus::kTruncated,
               "ASCII STL has no final 'endsolid' after " + std::to_string(triangles->size()) +
                   " facets: the file is truncated (a complete file ends with 'endsolid')");
        return status_;
      }
      if (!in_solid) {
        if (!IEquals(token, "solid")) {
          Fail(MeshIoStatus::kMalformed,
               "expected 'solid' or the end of the file after 'endsolid', found " + Quote(token));
          return status_;
        }
        cursor_.RestOfLine();
        in_solid = true;
      } else if (IEquals(token, "endsolid")) {
        cursor_.RestOfLine();
        in_solid = false;
      } else if (IEquals(token, "facet")) {
        StlTriangle t;
        if (!Facet(static_cast<int64_t>(triangles->size()), &t)) return status_;
        triangles->push_back(t);
      } else {
        Fail(MeshIoStatus::kMalformed, "expected 'facet' or 'endsolid', found " + Quote(token));
        return status_;
      }
    }
  }

 private:
  bool Facet(int64_t index, StlTriangle* t) {
    double ignored_normal[3];
    if (!Expect("normal") || !Number(&ignored_normal[0]) || !Number(&ignored_normal[1]) ||
        !Number(&ignored_normal[2]) || !Expect("outer") || !Expect("loop")) {
      return false;
    }
    int corners = 0;
    while (true) {
      const std::string_view token = cursor_.Next();
      if (token.empty()) return Truncated("'vertex' or 'endloop'");
      if (IEquals(token, "endloop")) break;
      if (!IEquals(token, "vertex")) {
        return Fail(MeshIoStatus::kMalformed,
                    "expected 'vertex' or 'endloop', found " + Quote(token));
      }
      if (corners == 3) {
        return Fail(MeshIoStatus::kMalformed,
                    "facet " + std::to_string(index) + " has more than 3 vertices");
      }
      Vec3& v = t->v[corners++];
      if (!Number(&v.x) || !Number(&v.y) || !Number(&v.z)) return false;
      if (!IsFinite(v)) {
        return Fail(MeshIoStatus::kNonFinite,
                    "triangle " + std::to_string(index) +
                        " has a non-finite (NaN or infinite) vertex coordinate");
      }
    }
    if (corners != 3) {
      return Fail(MeshIoStatus::kMalformed, "facet " + std::to_string(index) + " has " +
                                                std::to_string(corners) + " vertices, not 3");
    }
    return Expect("endfacet");
  }

  bool Expect(std::string_view keyword) {
    const std::string_view token = cursor_.Next();
    if (IEquals(token, keyword)) return true;
    const std::string expected = Quote(keyword);
    if (token.empty()) return Truncated(expected);
    return Fail(MeshIoStatus::kMalformed, "expected " + expected + ", found " + Quote(token));
  }

  bool Number(double* value) {
    std::string_view token = cursor_.Next();
    if (token.empty()) return Truncated("a number");
    const std::string_view digits = token.front() == '+' ? token.substr(1) : token;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), *value);
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
      // from_chars reports out-of-range magnitudes as errors; they are non-finite in effect.
      if (ec == std::errc::result_out_of_range) {
        return Fail(MeshIoStatus::kNonFinite, "number " + Quote(token) + " is out of range");
      }
      return Fail(MeshIoStatus::kMalformed, Quote(token) + " is not a number");
    }
    return true;
  }

  bool Truncated(const std::string& expected) {
    return Fail(MeshIoStatus::kTruncated,
                "ASCII STL ends inside a facet (truncated): expected " + expected);
  }

  bool Fail(MeshIoStatus status, const std::string& what) {
    status_ = status;
    *error_ = "line " + std::to_string(cursor_.line()) + ": " + what;
    return false;
  }

  Cursor cursor_;
  std::string* error_ = nullptr;
  MeshIoStatus status_ = MeshIoStatus::kOk;
};

}  // namespace

bool StartsWithSolidKeyword(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
  if (text.size() < 5 || !IEquals(text.substr(0, 5), "solid")) return false;
  return text.size() == 5 || IsSpace(text[5]);
}

MeshIoStatus ParseAsciiStl(std::string_view text, std::vector<StlTriangle>* triangles,
                           std::string* name, std::vector<std::string>* warnings,
                           std::string* error) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  Parser parser(text, error);
  const MeshIoStatus status = parser.Run(triangles, name, warnings);
  if (status != MeshIoStatus::kOk) triangles->clear();
  return status;
}

}  // namespace demcal::core
