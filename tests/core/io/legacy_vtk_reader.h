#pragma once
// Test helper: an independent reader for the subset of legacy VTK that the particle writer
// emits (POLYDATA with POINTS, VERTICES, field data and SCALARS/VECTORS point data, ASCII or
// big-endian BINARY), written from the format description (VTK User's Guide, "VTK File
// Formats"), not from the writer, so round trips check the writer against the spec.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace demcal::testing {

struct LegacyVtk {
  std::string title;
  bool binary = false;
  std::string dataset;
  std::map<std::string, std::vector<double>> field_data;  // name -> values
  std::vector<double> points;                             // x0 y0 z0 x1 ...
  std::vector<int32_t> vertices;                          // the raw cell list: 1 i 1 j ...
  int64_t point_data_count = -1;
  std::map<std::string, std::vector<double>>
      point_data;                                      // name -> values (3 per point for vectors)
  std::map<std::string, std::string> point_data_type;  // name -> "double", "int", ...
};

class LegacyVtkParser {
 public:
  explicit LegacyVtkParser(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream s;
    s << in.rdbuf();
    data_ = s.str();
  }

  LegacyVtk Parse() {
    LegacyVtk v;
    if (Line().rfind("# vtk DataFile Version", 0) != 0) throw std::runtime_error("bad magic");
    v.title = Line();
    const std::string encoding = Line();
    if (encoding != "ASCII" && encoding != "BINARY") throw std::runtime_error("bad encoding");
    binary_ = v.binary = encoding == "BINARY";
    std::istringstream ds(Line());
    std::string word;
    ds >> word >> v.dataset;
    if (word != "DATASET") throw std::runtime_error("expected DATASET");
    while (SkipBlank()) {
      std::istringstream h(Line());
      std::string key;
      h >> key;
      if (key == "FIELD") {
        std::string name;
        int arrays = 0;
        h >> name >> arrays;
        for (int a = 0; a < arrays; ++a) {
          std::istringstream ah(Line());
          std::string array_name, type;
          int components = 0;
          int64_t tuples = 0;
          ah >> array_name >> components >> tuples >> type;
          v.field_data[array_name] = Values(type, components * tuples);
        }
      } else if (key == "POINTS") {
        int64_t n = 0;
        std::string type;
        h >> n >> type;
        v.points = Values(type, 3 * n);
      } else if (key == "VERTICES") {
        int64_t cells = 0, size = 0;
        h >> cells >> size;
        for (double d : Values("int", size)) v.vertices.push_back(static_cast<int32_t>(d));
      } else if (key == "POINT_DATA") {
        h >> v.point_data_count;
      } else if (key == "SCALARS" || key == "VECTORS") {
        std::string name, type;
        int components = 1;
        h >> name >> type;
        if (key == "SCALARS" && !(h >> components)) components = 1;
        if (key == "VECTORS") components = 3;
        if (key == "SCALARS" && Line() != "LOOKUP_TABLE default")
          throw std::runtime_error("expected LOOKUP_TABLE default");
        v.point_data[name] = Values(type, components * v.point_data_count);
        v.point_data_type[name] = type;
      } else {
        throw std::runtime_error("unexpected keyword " + key);
      }
    }
    return v;
  }

 private:
  std::string Line() {
    const size_t end = data_.find('\n', pos_);
    if (end == std::string::npos) throw std::runtime_error("unexpected end of file");
    std::string line = data_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return line;
  }
  // Skips empty lines; false at end of file.
  bool SkipBlank() {
    while (pos_ < data_.size() && (data_[pos_] == '\n' || data_[pos_] == ' ')) ++pos_;
    return pos_ < data_.size();
  }
  std::vector<double> Values(const std::string& type, int64_t count) {
    std::vector<double> out;
    if (binary_) {
      const int bytes = type == "double" ? 8 : type == "float" || type == "int" ? 4 : 0;
      if (bytes == 0) throw std::runtime_error("unsupported binary type " + type);
      if (pos_ + count * bytes > data_.size()) throw std::runtime_error("truncated binary data");
      for (int64_t k = 0; k < count; ++k) {
        uint64_t bits = 0;
        for (int b = 0; b < bytes; ++b)
          bits = (bits << 8) | static_cast<unsigned char>(data_[pos_ + k * bytes + b]);
        if (type == "double") {
          double d;
          std::memcpy(&d, &bits, 8);
          out.push_back(d);
        } else if (type == "float") {
          const uint32_t b32 = static_cast<uint32_t>(bits);
          float f;
          std::memcpy(&f, &b32, 4);
          out.push_back(f);
        } else {
          out.push_back(static_cast<int32_t>(static_cast<uint32_t>(bits)));
        }
      }
      pos_ += count * bytes;
      if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_;
    } else {
      for (int64_t k = 0; k < count; ++k) {
        while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
        size_t end = pos_;
        while (end < data_.size() && !std::isspace(static_cast<unsigned char>(data_[end]))) ++end;
        if (end == pos_) throw std::runtime_error("too few values");
        out.push_back(std::stod(data_.substr(pos_, end - pos_)));
        pos_ = end;
      }
      if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_;
    }
    return out;
  }

  std::string data_;
  size_t pos_ = 0;
  bool binary_ = false;
};

inline LegacyVtk ReadLegacyVtk(const std::string& path) { return LegacyVtkParser(path).Parse(); }

}  // namespace demcal::testing
