#include "workflow/export/liggghts_walls.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <variant>

#include "workflow/export/liggghts_number.h"

namespace demcal::workflow {
namespace {

using core::Vec3;

// The axis (0, 1, 2) a unit vector lies along, or −1.
int AxisOf(const Vec3& v) {
  for (int a = 0; a < 3; ++a)
    if (std::abs(std::abs(v[a]) - 1) < 1e-12) return a;
  return -1;
}

// ASCII STL of triangles (a, b, c), normals from the winding.
class Stl {
 public:
  explicit Stl(const std::string& name) { out_ << "solid " << name << "\n"; }
  void Add(const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 n = Cross(b - a, c - a);
    const double l = Norm(n);
    if (l == 0) return;
    n = n / l;
    out_ << "  facet normal " << Num(n.x) << " " << Num(n.y) << " " << Num(n.z)
         << "\n    outer loop\n";
    for (const Vec3* p : {&a, &b, &c})
      out_ << "      vertex " << Num(p->x) << " " << Num(p->y) << " " << Num(p->z) << "\n";
    out_ << "    endloop\n  endfacet\n";
  }
  std::string Finish(const std::string& name) { return out_.str() + "endsolid " + name + "\n"; }

 private:
  std::ostringstream out_;
};

// Two unit vectors completing `axis` to an orthonormal frame.
void Frame(const Vec3& axis, Vec3* u, Vec3* v) {
  const Vec3 helper = std::abs(axis.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  *u = Cross(axis, helper);
  *u = *u / Norm(*u);
  *v = Cross(axis, *u);
}

// A surface of revolution between (h0, r0) and (h1, r1) about `axis` through `point`.
void Revolution(const Vec3& point, const Vec3& axis, double h0, double r0, double h1, double r1,
                Stl* stl) {
  Vec3 u, v;
  Frame(axis, &u, &v);
  for (int k = 0; k < kMeshSegments; ++k) {
    const double a0 = 2 * std::numbers::pi * k / kMeshSegments;
    const double a1 = 2 * std::numbers::pi * (k + 1) / kMeshSegments;
    const Vec3 e0 = std::cos(a0) * u + std::sin(a0) * v, e1 = std::cos(a1) * u + std::sin(a1) * v;
    const Vec3 p00 = point + h0 * axis + r0 * e0, p01 = point + h0 * axis + r0 * e1;
    const Vec3 p10 = point + h1 * axis + r1 * e0, p11 = point + h1 * axis + r1 * e1;
    stl->Add(p00, p01, p11);
    stl->Add(p00, p11, p10);
  }
}

std::string WallName(const core::Wall& w, size_t k) {
  return "wall '" + (w.name.empty() ? "walls[" + std::to_string(k) + "]" : w.name) + "'";
}

// A file-name-safe form of a wall's name.
std::string FileStem(const core::Wall& w, size_t k) {
  std::string s = "wall" + std::to_string(k + 1);
  if (!w.name.empty()) s += "_";
  for (char c : w.name) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s;
}

}  // namespace

bool LiggghtsWalls(const core::Scene& scene, const std::string& law, LiggghtsWallSet* out,
                   std::string* error) {
  *out = {};
  std::ostringstream cmd;
  std::vector<std::string> meshes;
  const char* axis_name = "xyz";
  for (size_t k = 0; k < scene.walls.size(); ++k) {
    const core::Wall& w = scene.walls[k];
    const std::string id = "w" + std::to_string(k + 1);
    const int type = w.material + 1;
    if (w.Moves()) {
      *error = WallName(w, k) + ": a moving wall is not exported";
      return false;
    }
    out->materials.push_back(w.material);
    cmd << "# " << WallName(w, k) << " (" << core::ShapeName(w.shape) << ")\n";
    const std::string head = "fix " + id + " all wall/gran " + law;
    std::string stl;
    if (const auto* plane = std::get_if<core::PlaneSurface>(&w.shape)) {
      const int a = AxisOf(plane->normal);
      if (a < 0) {
        *error = WallName(w, k) + ": a plane not normal to x, y or z is not exported";
        return false;
      }
      cmd << head << " primitive type " << type << " " << axis_name[a] << "plane "
          << Num(plane->point_m[a]) << "\n";
    } else if (const auto* cyl = std::get_if<core::CylinderSurface>(&w.shape)) {
      const int a = AxisOf(cyl->axis);
      if (a >= 0 && std::isinf(cyl->axial_min_m) && std::isinf(cyl->axial_max_m)) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        cmd << head << " primitive type " << type << " " << axis_name[a] << "cylinder "
            << Num(cyl->radius_m) << " " << Num(cyl->axis_point_m[std::min(b, c)]) << " "
            << Num(cyl->axis_point_m[std::max(b, c)]) << "\n";
      } else if (std::isinf(cyl->axial_min_m) || std::isinf(cyl->axial_max_m)) {
        *error = WallName(w, k) + ": a half-infinite or oblique infinite cylinder is not exported";
        return false;
      } else {
        Stl s(id);
        Revolution(cyl->axis_point_m, cyl->axis, cyl->axial_min_m, cyl->radius_m, cyl->axial_max_m,
                   cyl->radius_m, &s);
        stl = s.Finish(id);
      }
    } else if (const auto* cone = std::get_if<core::ConeFrustumSurface>(&w.shape)) {
      Stl s(id);
      Revolution(cone->axis_point_m, cone->axis, cone->height0_m, cone->radius0_m, cone->height1_m,
                 cone->radius1_m, &s);
      stl = s.Finish(id);
    } else if (const auto* mesh = std::get_if<core::MeshRef>(&w.shape)) {
      Stl s(id);
      for (size_t t = 0; t < mesh->mesh->NumTriangles(); ++t) {
        const auto& c = mesh->mesh->TriangleVertices(static_cast<int32_t>(t));
        s.Add(mesh->mesh->Vertex(c[0]) + mesh->offset_m, mesh->mesh->Vertex(c[1]) + mesh->offset_m,
              mesh->mesh->Vertex(c[2]) + mesh->offset_m);
      }
      stl = s.Finish(id);
    }
    if (!stl.empty()) {
      const std::string path = "meshes/" + FileStem(w, k) + ".stl";
      out->stl_files.emplace_back(path, stl);
      cmd << "fix " << id << "_mesh all mesh/surface file " << path << " type " << type << "\n";
      meshes.push_back(id + "_mesh");
      if (std::isfinite(w.remove_at_s)) {
        // LIGGGHTS touches every mesh through one fix wall/gran, which cannot drop one mesh.
        *error = WallName(w, k) + ": a mesh wall taken away during the run is not exported";
        return false;
      }
    }
    out->fix_ids.push_back(stl.empty() ? id : id + "_mesh");
    if (std::isfinite(w.remove_at_s)) out->removals.emplace_back(w.remove_at_s, id);
  }
  // LIGGGHTS allows one fix wall/gran of type mesh, holding every mesh.
  if (!meshes.empty()) {
    cmd << "fix meshes all wall/gran " << law << " mesh n_meshes " << meshes.size() << " meshes";
    for (const std::string& m : meshes) cmd << " " << m;
    cmd << "\n";
  }
  out->commands = cmd.str();
  return true;
}

}  // namespace demcal::workflow
