// WallContacts::Rebuild keeps the wall row of a particle whose neighbour-list reference did not
// move and re-lists the others (wall_contacts.h). What must hold: a kept row still holds every
// wall and mesh triangle the particle can reach before the next rebuild (it stays within skin/2
// of its reference), a re-listed row is what a fresh listing at the particle's position gives,
// and a wall removed since is dropped from kept rows too.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <random>
#include <type_traits>
#include <vector>

#include <tbb/task_arena.h>

#include "core/walls/wall_contacts.h"
#include "tests/core/walls/wall_test_support.h"

using namespace demcal::core;

namespace {

// Particle i's candidates: wall index -> its near triangles (empty unless a static mesh).
using Row = std::map<uint32_t, std::vector<int32_t>>;

// Reads the compressed rows through WallContacts::Serialize (its archive interface), so the
// test sees the stored rows without a test-only accessor.
struct RowsReader {
  int field = 0;
  std::vector<uint32_t> start, index, mesh_slots, near_start;
  std::vector<int32_t> near;
  template <class T>
  void Vector(std::vector<T>& v) {
    const int f = field++;  // start, index, history, active, mesh_slots, mesh_history, load, ...
    if constexpr (std::is_same_v<T, uint32_t>) {
      if (f == 0) start = v;
      if (f == 1) index = v;
      if (f == 4) mesh_slots = v;
      if (f == 7) near_start = v;
    }
    if constexpr (std::is_same_v<T, int32_t>) near = v;
  }
};

std::vector<Row> Rows(WallContacts contacts) {
  RowsReader r;
  contacts.Serialize(r);
  std::vector<Row> rows(r.start.size() - 1);
  for (size_t i = 0; i + 1 < r.start.size(); ++i) {
    for (uint32_t e = r.start[i]; e < r.start[i + 1]; ++e) {
      std::vector<int32_t>& near = rows[i][r.index[e]];
      const uint32_t s = r.mesh_slots[e];
      if (s != ~uint32_t{0})
        near.assign(r.near.begin() + r.near_start[s], r.near.begin() + r.near_start[s + 1]);
    }
  }
  return rows;
}

// Every wall and triangle of `inner` is in `outer`.
bool Contains(const Row& outer, const Row& inner) {
  for (const auto& [wall, near] : inner) {
    auto it = outer.find(wall);
    if (it == outer.end() || !std::includes(it->second.begin(), it->second.end(), near.begin(),
                                            near.end()))
      return false;
  }
  return true;
}

// A plane floor, an inside cylinder, an open mesh box and a mesh plate, all static.
constexpr uint32_t kFloor = 0, kBox = 2;  // indices in Walls()
std::vector<Wall> Walls() {
  std::vector<Wall> walls;
  walls.push_back(Wall(PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}));
  CylinderSurface c;
  c.radius_m = 0.02;
  walls.push_back(Wall("silo", 0, c));
  walls.push_back(wall_test::MeshBox("box", {-0.015, -0.015, 0.001}, {0.015, 0.015, 0.05}, true));
  walls.push_back(wall_test::MeshPlate("plate", 0.012, 0.006));
  return walls;
}

WallContacts Fresh(const Particles& p, const std::vector<Wall>& walls, double skin) {
  WallContacts contacts;
  contacts.Rebuild(p, {}, {}, {}, walls, skin);
  return contacts;
}

// Seeded uniform draws over the walls' region (Walls()).
struct Draw {
  std::mt19937_64 rng;
  std::uniform_real_distribution<double> u{0, 1};
  explicit Draw(unsigned seed) : rng(seed) {}
  double U() { return u(rng); }
  Vec3 Point() { return {-0.019 + 0.038 * U(), -0.019 + 0.038 * U(), 0.012 * U()}; }
};

// `count` spheres of one radius at drawn points.
Particles Spheres(int count, double radius, Draw& draw) {
  Particles p;
  for (int k = 0; k < count; ++k) p.Add(k, 0, 0, radius, 2500, draw.Point(), {}, {});
  return p;
}

}  // namespace

TEST_CASE("a kept wall row covers what its particle can reach; a moved one is re-listed",
          "[unit][geometry]") {
  const double radius = 0.001, skin = 0.0005;
  const std::vector<Wall> walls = Walls();
  Draw draw(11);
  Particles p = Spheres(400, radius, draw);
  const std::vector<Vec3> before = p.position_m;
  WallContacts contacts;
  contacts.Rebuild(p, {}, before, {}, walls, skin);
  const std::vector<Row> old_rows = Rows(contacts);

  // Half the particles keep their reference and drift up to skin/2 from it; the others jump
  // anywhere (far from or onto a wall) and are re-referenced there, as a neighbour rebuild does.
  std::vector<Vec3> reference = before;
  std::vector<bool> kept(p.Size());
  for (size_t i = 0; i < p.Size(); ++i) {
    kept[i] = i % 2 == 0;
    if (kept[i]) {
      const Vec3 d{draw.U() - 0.5, draw.U() - 0.5, draw.U() - 0.5};
      p.position_m[i] = before[i] + (0.5 * skin * draw.U()) * d / Norm(d);
    } else {
      p.position_m[i] = reference[i] = draw.Point();
    }
  }
  contacts.Rebuild(p, before, reference, {}, walls, skin);
  const std::vector<Row> rows = Rows(contacts);
  const std::vector<Row> reachable = Rows(Fresh(p, walls, 0.5 * skin));
  const std::vector<Row> listed_here = Rows(Fresh(p, walls, skin));
  int kept_rows = 0, relisted_changed = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    INFO("particle " << i << (kept[i] ? " (kept)" : " (re-listed)"));
    CHECK(Contains(rows[i], reachable[i]));
    if (kept[i]) {
      CHECK(rows[i] == old_rows[i]);
      kept_rows += !rows[i].empty();
    } else {
      CHECK(rows[i] == listed_here[i]);
      relisted_changed += rows[i] != old_rows[i];
    }
  }
  CHECK(kept_rows > 100);         // the draw put many kept particles near walls
  CHECK(relisted_changed > 100);  // and the jumps changed what re-listed particles see

  // A kept row loses a wall removed since; a displacement beyond skin/2 with the reference
  // unchanged (a periodic wrap, which the list's minimum-image test does not see) re-lists.
  std::vector<Wall> fewer = walls;
  fewer[kBox].removed = true;
  size_t wrapped = 0;  // a kept particle near the floor
  while (wrapped < p.Size() && !rows[wrapped].count(kFloor)) wrapped += 2;
  REQUIRE(wrapped < p.Size());
  p.position_m[wrapped] = {0, 0, 0.03};  // clear of every wall
  contacts.Rebuild(p, reference, reference, {}, fewer, skin);
  const std::vector<Row> after_removal = Rows(contacts);
  CHECK(after_removal[wrapped].empty());
  for (size_t i = 0; i < p.Size(); ++i) {
    if (i == wrapped) continue;
    Row expected = rows[i];
    expected.erase(kBox);
    CHECK(after_removal[i] == expected);
  }
}

namespace {
// Every stored array of `contacts`, byte for byte (through its Serialize archive interface).
struct ByteArchive {
  std::vector<unsigned char> bytes;
  template <class T>
  void Vector(std::vector<T>& v) {
    const auto* b = reinterpret_cast<const unsigned char*>(v.data());
    bytes.insert(bytes.end(), b, b + v.size() * sizeof(T));
    bytes.push_back(0xFF);  // a boundary, so that bytes moved between arrays differ
  }
};
std::vector<unsigned char> Bytes(WallContacts contacts) {
  ByteArchive a;
  contacts.Serialize(a);
  return a.bytes;
}
}  // namespace

TEST_CASE("wall rows listed in blocks on several threads are the one-thread rows",
          "[unit][geometry][determinism]") {
  // 5,000 particles: three blocks of rows (WallContacts::kRebuildBlock is 2,048), so rows,
  // mesh slots and near triangles are joined across block boundaries.
  const double radius = 0.001, skin = 0.0005;
  const std::vector<Wall> walls = Walls();
  Draw draw(7);
  Particles p = Spheres(5000, radius, draw);
  const std::vector<Vec3> before = p.position_m;
  std::vector<Vec3> reference = before;
  for (size_t i = 1; i < p.Size(); i += 2) p.position_m[i] = reference[i] = draw.Point();

  auto listed_with = [&](int threads) {
    tbb::task_arena arena(threads);
    return arena.execute([&] {
      WallContacts contacts;
      contacts.Rebuild(p, {}, before, {}, walls, skin);  // the first listing
      contacts.Rebuild(p, before, reference, {}, walls, skin);  // half kept, half re-listed
      return contacts;
    });
  };
  const WallContacts one = listed_with(1);
  CHECK(Bytes(one) == Bytes(listed_with(4)));
  CHECK(Bytes(one) == Bytes(listed_with(3)));

  // In every block, a re-listed row is what the particle alone, listed fresh, gets (one block:
  // no join involved).
  const std::vector<Row> rows = Rows(one);
  size_t meshes_in_last_block = 0;
  for (size_t i = 1; i < p.Size(); i += 2) {
    INFO("particle " << i);
    Particles alone;
    alone.Add(0, 0, 0, radius, 2500, p.position_m[i], {}, {});
    CHECK(rows[i] == Rows(Fresh(alone, walls, skin))[0]);
    meshes_in_last_block += i >= 4096 && rows[i].count(kBox);
  }
  CHECK(meshes_in_last_block > 10);  // mesh slots and triangles offset past two blocks
}
