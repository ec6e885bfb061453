#include "grid_clustering.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace kestrel::clustering {

namespace {

// Union-find over cells, with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_, size_;
};

// The 3D cell index packed into one key: 21 bits per axis, offset to be non-negative.
constexpr std::int64_t kAxisBits = 21;
constexpr std::int64_t kAxisOffset = std::int64_t{1} << (kAxisBits - 1);
std::uint64_t pack(std::int64_t i, std::int64_t j, std::int64_t k) {
  const auto axis = [](std::int64_t v) { return static_cast<std::uint64_t>(v + kAxisOffset); };
  return (axis(i) << (2 * kAxisBits)) | (axis(j) << kAxisBits) | axis(k);
}

// PCL's test (FLANN L2 on floats): squared distance summed in float, strictly below r^2.
bool linked(const pcl::PointXYZ& a, const pcl::PointXYZ& b, float radius_sq) {
  const float dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  float d = dx * dx;
  d += dy * dy;
  d += dz * dz;
  return d < radius_sq;
}

struct Cell {
  std::int64_t i, j, k;
  std::vector<int> points;
};

}  // namespace

std::vector<std::vector<int>> grid_clusters(const pcl::PointCloud<pcl::PointXYZ>& cloud, double tolerance,
                                            int min_points, int max_points) {
  std::vector<std::vector<int>> out;
  if (cloud.empty() || tolerance <= 0) return out;
  // PCL passes the tolerance on as a float, squares it in double and rounds the square to float.
  const double tolerance_f = static_cast<float>(tolerance);
  const float radius_sq = static_cast<float>(tolerance_f * tolerance_f);
  // Any two points of a cell are closer than the tolerance: its diagonal is side * sqrt(3).
  const double side = tolerance / std::sqrt(3.0) * (1.0 - 1e-4);
  const double max_index = static_cast<double>(kAxisOffset - 4);

  std::vector<Cell> cells;
  std::unordered_map<std::uint64_t, std::size_t> cell_of_key;
  cell_of_key.reserve(cloud.size());
  std::vector<std::size_t> cell_of_point(cloud.size());
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    const auto& q = cloud[p];
    const double idx[3] = {std::floor(q.x / side), std::floor(q.y / side), std::floor(q.z / side)};
    std::uint64_t key = 0;
    if (std::all_of(idx, idx + 3, [&](double v) { return std::abs(v) <= max_index; })) {
      key =
          pack(static_cast<std::int64_t>(idx[0]), static_cast<std::int64_t>(idx[1]), static_cast<std::int64_t>(idx[2]));
    } else {
      // Non-finite, or hundreds of kilometres away: a cell of its own that no neighbour search
      // reaches (PCL's search never links such a point either).
      cell_of_point[p] = cells.size();
      cells.push_back(Cell{kAxisOffset, kAxisOffset, kAxisOffset, {static_cast<int>(p)}});
      continue;
    }
    const auto [it, added] = cell_of_key.try_emplace(key, cells.size());
    if (added)
      cells.push_back(Cell{
          static_cast<std::int64_t>(idx[0]), static_cast<std::int64_t>(idx[1]), static_cast<std::int64_t>(idx[2]), {}});
    cells[it->second].points.push_back(static_cast<int>(p));
    cell_of_point[p] = it->second;
  }

  DisjointSets sets(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const Cell& a = cells[c];
    if (a.i == kAxisOffset) continue;  // a lone far point
    for (std::int64_t di = -2; di <= 2; ++di)
      for (std::int64_t dj = -2; dj <= 2; ++dj)
        for (std::int64_t dk = -2; dk <= 2; ++dk) {
          // Each unordered pair of cells once.
          if (std::make_tuple(di, dj, dk) <= std::make_tuple(std::int64_t{0}, std::int64_t{0}, std::int64_t{0}))
            continue;
          const auto it = cell_of_key.find(pack(a.i + di, a.j + dj, a.k + dk));
          if (it == cell_of_key.end() || sets.find(c) == sets.find(it->second)) continue;
          const Cell& b = cells[it->second];
          bool joined = false;
          for (int pa : a.points) {
            for (int pb : b.points)
              if (linked(cloud[static_cast<std::size_t>(pa)], cloud[static_cast<std::size_t>(pb)], radius_sq)) {
                sets.join(c, it->second);
                joined = true;
                break;
              }
            if (joined) break;
          }
        }
  }

  std::unordered_map<std::size_t, std::vector<int>> members;
  for (std::size_t p = 0; p < cloud.size(); ++p) members[sets.find(cell_of_point[p])].push_back(static_cast<int>(p));
  for (auto& [root, indices] : members) {
    const auto n = static_cast<int>(indices.size());
    if (n >= min_points && n <= max_points) out.push_back(std::move(indices));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() > b.size() : a.front() < b.front();
  });
  return out;
}

}  // namespace kestrel::clustering
