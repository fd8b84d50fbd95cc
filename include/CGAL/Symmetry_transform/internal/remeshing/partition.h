// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PARTITION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PARTITION_H

// The symmetric partition of the working mesh into proxies (thesis, Section 5.1.2), and its
// Lloyd steps: flooding, fitting and teleportation. A proxy is a plane with up to one connected
// patch per transform (the identity and the reflection through each plane). A patch is labelled
// `proxy * transforms + transform` (transform 0: the identity, j + 1: plane j).
//
// Flooding: one priority queue, in increasing error, as in VSA; when a face joins a patch, its
// neighbours are queued for that patch and the face nearest to its mirror image (mirrors.h) is
// offered to the mirrored patch. The mirror joins at once if it fits that patch about as well as
// the face fits its own (on an exactly symmetric mesh it always does, so that the partition
// stays mirror-symmetric whatever the order of equal errors), else it is queued with its own
// error and competes as any face. A patch stays connected: a face only joins a non-empty patch
// next to one of its faces. Where a face has a mirror through a plane, a patch of the identity
// or of that plane does not grow across the plane: its mirrored patch takes over there, so that
// a proxy spanning the plane is cut along it into two mirrored patches.
//
// Metric (thesis, "Error Metric"): E(t, P) = a_t (alpha |c_t - c_P|^2 / A_avg + (1 - alpha)
// |n_t - n_P|^2), with c and n centroids and unit normals, P's parameters moved by the patch's
// transform, a_t the area of t and A_avg the mean face area: the area-weighted form of the
// thesis's metric, which is L2,1 (CGAL's default) for alpha = 0.
//
// The seeding is in seeding.h, the mirror-consistent boundaries in mirror_boundaries.h, the
// whole sequence in proxy_generation.h.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/remeshing/settings.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A mirror face fits its mirrored patch "about as well" as the face it mirrors fits its own if
// its error is at most this factor times that error, plus this fraction of its area (at
// alpha = 0, the error of a normal deviation |n_t - n_P| of 0.1): loose enough for rounding and
// the small asymmetries of a nearly symmetric mesh, tight enough that a mirror that fits clearly
// worse competes in the queue instead.
constexpr double mirror_fit_factor = 2.;
constexpr double mirror_fit_slack = 0.01;

// Patch teleportation: a patch of less than this fraction of the area of its proxy's largest
// patch is closed for the next partition (a sliver left by the flooding order).
constexpr double closed_patch_fraction = 0.05;

// Proxy teleportation (CGAL's teleport_proxies): a merge of two proxies is done if it costs
// less than this fraction of the error of the worst proxy.
constexpr double max_merge_cost = 0.5;

class Symmetric_partition
{
public:
  static constexpr std::size_t none = Remeshing_mesh::none;

  struct Proxy
  {
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(), center = Eigen::Vector3d::Zero(); // in the identity frame
    std::size_t seed = none, seed_label = none;
    double error = 0.;
    // Moments in the identity frame, for the error of a merge: area, sum of a n, sum of a c, sum of a |c|^2.
    double area = 0., squares = 0.;
    Eigen::Vector3d normals = Eigen::Vector3d::Zero(), centers = Eigen::Vector3d::Zero();
  };

  // `mirror[f * planes + j]`: the mirror face of f through plane j, or `none` (mirror_faces()).
  Symmetric_partition(const Remeshing_mesh& mesh, const Remeshing_settings& settings, const std::vector<std::size_t>& mirror);

  const Remeshing_mesh& mesh() const { return mesh_; }
  const Remeshing_settings& settings() const { return settings_; }
  std::size_t transforms() const { return transform_count_; }
  std::size_t plane_count() const { return plane_count_; }
  const std::vector<std::size_t>& labels() const { return label_; }
  const std::vector<Proxy>& proxies() const { return proxies_; }
  std::size_t proxy_of(std::size_t label) const { return label / transform_count_; }
  std::size_t mirror_face(std::size_t f, std::size_t plane) const { return mirror_[f * plane_count_ + plane]; }
  // Whether the patch is closed by patch teleportation (see fit()).
  bool is_closed(std::size_t label) const { return closed_[label] != 0; }

  // The plane of a patch: the proxy's, moved by the patch's transform.
  const Eigen::Vector3d& patch_normal(std::size_t label) const { return patch_plane_[label].normal; }
  const Eigen::Vector3d& patch_center(std::size_t label) const { return patch_plane_[label].center; }
  double patch_area(std::size_t label) const { return patch_area_[label]; }

  double total_error() const;

  // The error of face f for the patch `label`.
  double error(std::size_t f, std::size_t label) const;

  // Whether an error `e` of face f for a mirrored patch is about that of the face it mirrors
  // (`reference`): on an exactly symmetric mesh it always is.
  bool fits_about_as_well(std::size_t f, double e, double reference) const;

  // Whether face f shares an edge with the patch, not counting edges on the planes of
  // `not_across` (a bit per plane).
  bool next_to(std::size_t f, std::size_t label, std::uint64_t not_across = 0) const;

  // A new proxy, the plane of face f, seeded there.
  std::size_t add_proxy_at(std::size_t f);

  // One proxy per piece (`piece` of each face, `first_faces` of each piece), seeded at the
  // piece's first face and fitted to the piece, every face in the identity patch of its piece.
  void reset_to_pieces(const std::vector<std::size_t>& piece, const std::vector<std::size_t>& first_faces);

  // Moves face f to the patch `label` (`none`: to no patch).
  void relabel(std::size_t f, std::size_t label);

  // One Lloyd iteration: flooding, then fitting; returns the total error.
  double iterate();

  double run_iterations(std::size_t count);

  // The face of largest error of the worst proxy, other than its seed, or `none`.
  std::size_t worst_face(std::size_t* worst_proxy = nullptr) const;

  // Proxy parameters from their faces (area-weighted normal and centroid in the identity frame),
  // then errors, seeds (the best face of each proxy) and patch areas. A patch much smaller than
  // its proxy's largest is closed for the next partition (patch teleportation): its faces go
  // to other patches, and the proxy may grow it again afterwards.
  void fit();

  // Proxy teleportation (CGAL's teleport_proxies): the adjacent pair whose merge costs least is
  // merged, and the freed proxy is moved to the worst face of the worst proxy, if the merge costs
  // less than `max_merge_cost` times the worst proxy's error.
  bool teleport();

  // Unlabelled faces join a neighbouring patch (those of a component with none, patch 0).
  void join_neighbouring_patches();

private:
  // A face offered to a patch, ordered by error, then by face and patch (a deterministic order).
  struct Candidate
  {
    double error;
    std::uint32_t face, label;
    bool operator>(const Candidate& c) const { return error > c.error || (error == c.error && key() > c.key()); }
    std::uint64_t key() const { return (std::uint64_t(face) << 32) | label; }
  };

  // What the error of a face reads, packed in one record of 64 bytes (a cache line; `padding`
  // fills it), for the speed of the flooding, which computes an error per queued face.
  struct Face_data
  {
    Eigen::Vector3d normal, centroid;
    double area, padding;
  };

  // The plane of a patch, in the patch's frame.
  struct Patch_plane
  {
    Eigen::Vector3d normal, center;
  };

  void pack_face_data();

  // Face data of face f in the frame of transform i.
  Eigen::Vector3d frame_normal(std::size_t f, std::size_t i) const;
  Eigen::Vector3d frame_centroid(std::size_t f, std::size_t i) const;

  void update_patch_planes(std::size_t p);

  void resize_labels();

  bool can_join(std::size_t f, std::size_t label) const;

  // Face f joins the patch `label`, and the mirrors that fit about as well join theirs at once.
  void assign(std::size_t f, std::size_t label);

  // The free neighbours of face g, queued for g's patch.
  void queue_neighbours(std::size_t g, std::size_t l);

  // The free mirrors of face g offered to the mirrored patches of g's patch (reflections of the
  // identity patch, and back to it): joined at once if they fit about as well, else queued.
  void offer_mirrors(std::size_t g, std::size_t l);

  void flood();

  // The partition step: every face to a patch, flooding from the proxies' seeds.
  void flood_from_seeds();

  // The moments of each proxy over its faces, each moved back by its patch's transform, and
  // the proxy's plane from them; errors and seeds reset.
  void fit_planes();

  // Patch teleportation: a patch under `closed_patch_fraction` of its proxy's largest is closed
  // (the seed's patch excepted).
  void close_small_patches();

  // Optimal error of the moments of a set of faces (in the identity frame).
  double moment_error(double area, const Eigen::Vector3d& normals, const Eigen::Vector3d& centers, double squares) const;

  struct Merge
  {
    std::size_t first, second;
    double cost;
  };

  // The adjacent pair of proxies (neither the worst) whose merge increases the error least.
  Merge cheapest_merge(std::size_t worst) const;

  const Remeshing_mesh& mesh_;
  const Remeshing_settings& settings_;
  const std::vector<std::size_t>& mirror_;
  const std::size_t plane_count_, transform_count_;
  double normal_weight_ = 1., position_weight_ = 0.; // of the metric: 1 - alpha, alpha / A_avg
  std::vector<Proxy> proxies_;
  std::vector<std::size_t> label_, patch_face_count_; // per face its patch; per patch its number of faces
  std::vector<Patch_plane> patch_plane_;
  std::vector<double> patch_area_;
  std::vector<char> closed_; // per patch: closed by patch teleportation
  std::vector<Face_data> face_data_;
  std::vector<std::size_t> neighbor_; // mesh_.neighbor(h), copied for the speed of the flooding
  std::vector<std::uint64_t> edge_planes_, mirror_planes_;
  std::vector<double> best_queued_error_; // per face: the least error it is queued with
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
  std::vector<Candidate> joins_; // mirrors joining at once
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Symmetric_partition::Symmetric_partition(const Remeshing_mesh& mesh, const Remeshing_settings& settings, const std::vector<std::size_t>& mirror)
  : mesh_(mesh), settings_(settings), mirror_(mirror), plane_count_(settings.planes.size()),
    transform_count_(plane_count_ + 1)
{
  double total = 0.;
  for(double a : mesh_.area) total += a;
  const double average_area = total / double(mesh_.number_of_faces());
  normal_weight_ = 1. - settings_.position_weight;
  position_weight_ = average_area > 0. ? settings_.position_weight / average_area : 0.;
  label_.assign(mesh_.number_of_faces(), none);
  pack_face_data();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Symmetric_partition::total_error() const
{
  double e = 0.;
  for(const Proxy& p : proxies_) e += p.error;
  return e;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Symmetric_partition::error(std::size_t f, std::size_t label) const
{
  const Face_data& d = face_data_[f];
  const Patch_plane& t = patch_plane_[label];
  double n2 = 0., c2 = 0.;
  for(int i = 0; i < 3; ++i) n2 += (d.normal[i] - t.normal[i]) * (d.normal[i] - t.normal[i]);
  if(position_weight_ > 0.)
    for(int i = 0; i < 3; ++i) c2 += (d.centroid[i] - t.center[i]) * (d.centroid[i] - t.center[i]);
  return d.area * (normal_weight_ * n2 + position_weight_ * c2);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Symmetric_partition::fits_about_as_well(std::size_t f, double e, double reference) const
{
  return e <= mirror_fit_factor * reference + mirror_fit_slack * face_data_[f].area;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Symmetric_partition::next_to(std::size_t f, std::size_t label, std::uint64_t not_across) const
{
  for(int i = 0; i < 3; ++i) {
    const std::size_t g = neighbor_[3 * f + i];
    if(g != none && label_[g] == label && !(edge_planes_[3 * f + i] & not_across)) return true;
  }
  return false;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Symmetric_partition::add_proxy_at(std::size_t f)
{
  Proxy p;
  p.normal = mesh_.normal[f].squaredNorm() > 0. ? mesh_.normal[f] : Eigen::Vector3d::UnitZ();
  p.center = mesh_.centroid[f];
  p.seed = f;
  p.seed_label = proxies_.size() * transform_count_;
  proxies_.push_back(p);
  resize_labels();
  return proxies_.size() - 1;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::reset_to_pieces(const std::vector<std::size_t>& piece, const std::vector<std::size_t>& first_faces)
{
  proxies_.clear();
  for(std::size_t f : first_faces) add_proxy_at(f);
  for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f) label_[f] = piece[f] * transform_count_;
  patch_face_count_.assign(proxies_.size() * transform_count_, 0);
  fit();
  std::fill(closed_.begin(), closed_.end(), 0);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::relabel(std::size_t f, std::size_t label)
{
  if(label_[f] != none) --patch_face_count_[label_[f]];
  label_[f] = label;
  if(label != none) ++patch_face_count_[label];
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Symmetric_partition::iterate()
{
  flood_from_seeds();
  fit();
  return total_error();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Symmetric_partition::run_iterations(std::size_t count)
{
  double e = total_error();
  for(std::size_t i = 0; i < count; ++i) e = iterate();
  return e;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Symmetric_partition::worst_face(std::size_t* worst_proxy) const
{
  std::size_t worst = 0;
  for(std::size_t p = 1; p < proxies_.size(); ++p)
    if(proxies_[p].error > proxies_[worst].error) worst = p;
  std::size_t face = none;
  double largest = -1.;
  for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f)
    if(label_[f] / transform_count_ == worst && f != proxies_[worst].seed) {
      const double e = error(f, label_[f]);
      if(e > largest) {
        largest = e;
        face = f;
      }
    }
  if(worst_proxy) *worst_proxy = worst;
  return face;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::fit()
{
  fit_planes();
  std::fill(patch_area_.begin(), patch_area_.end(), 0.);
  std::vector<double> best(proxies_.size(), 0.);
  for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f) {
    const std::size_t l = label_[f];
    Proxy& p = proxies_[l / transform_count_];
    const double e = error(f, l);
    p.error += e;
    patch_area_[l] += mesh_.area[f];
    if(p.seed == none || e < best[l / transform_count_]) {
      p.seed = f;
      p.seed_label = l;
      best[l / transform_count_] = e;
    }
  }
  close_small_patches();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Symmetric_partition::teleport()
{
  std::size_t worst = 0;
  const std::size_t target = worst_face(&worst);
  if(target == none) return false;
  const auto [a, b, cost] = cheapest_merge(worst);
  if(a == none || cost > proxies_[worst].error * max_merge_cost) return false;
  Proxy& x = proxies_[a];
  const Proxy& y = proxies_[b];
  x.area += y.area;
  x.normals += y.normals;
  x.centers += y.centers;
  x.squares += y.squares;
  if(x.normals.squaredNorm() > 0.) x.normal = x.normals.normalized();
  if(x.area > 0.) x.center = x.centers / x.area;
  update_patch_planes(a);
  Proxy moved;
  moved.normal = mesh_.normal[target].squaredNorm() > 0. ? mesh_.normal[target] : Eigen::Vector3d::UnitZ();
  moved.center = mesh_.centroid[target];
  moved.seed = target;
  moved.seed_label = b * transform_count_;
  proxies_[b] = moved;
  update_patch_planes(b);
  for(std::size_t i = 0; i < transform_count_; ++i) closed_[b * transform_count_ + i] = closed_[a * transform_count_ + i] = 0;
  return true;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::join_neighbouring_patches()
{
  const std::size_t nf = mesh_.number_of_faces();
  for(bool changed = true; changed;) {
    changed = false;
    for(std::size_t f = 0; f < nf; ++f) {
      if(label_[f] != none) continue;
      for(int h = 0; h < 3 && label_[f] == none; ++h) {
        const std::size_t n = mesh_.neighbor(3 * f + h);
        if(n != none && label_[n] != none) {
          relabel(f, label_[n]);
          changed = true;
        }
      }
    }
  }
  for(std::size_t f = 0; f < nf; ++f)
    if(label_[f] == none) relabel(f, 0);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::pack_face_data()
{
  const std::size_t nf = mesh_.number_of_faces();
  face_data_.resize(nf);
  neighbor_.resize(3 * nf);
  for(std::size_t f = 0; f < nf; ++f) {
    face_data_[f].normal = mesh_.normal[f];
    face_data_[f].centroid = mesh_.centroid[f];
    face_data_[f].area = mesh_.area[f];
    for(int i = 0; i < 3; ++i) neighbor_[3 * f + i] = mesh_.neighbor(3 * f + i);
  }
  // Per halfedge the planes it lies on, per face the planes through which it has a mirror.
  edge_planes_.assign(3 * nf, 0);
  mirror_planes_.assign(nf, 0);
  for(std::size_t h = 0; h < edge_planes_.size(); ++h)
    edge_planes_[h] = mesh_.vertex_planes[mesh_.source(h)] & mesh_.vertex_planes[mesh_.target(h)];
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t j = 0; j < plane_count_; ++j)
      if(mirror_face(f, j) != none) mirror_planes_[f] |= std::uint64_t(1) << j;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::Vector3d Symmetric_partition::frame_normal(std::size_t f, std::size_t i) const
{
  return i == 0 ? mesh_.normal[f] : reflect_vector(settings_.planes[i - 1], mesh_.normal[f]);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::Vector3d Symmetric_partition::frame_centroid(std::size_t f, std::size_t i) const
{
  return i == 0 ? mesh_.centroid[f] : settings_.planes[i - 1].reflect(mesh_.centroid[f]);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::update_patch_planes(std::size_t p)
{
  for(std::size_t i = 0; i < transform_count_; ++i) {
    Patch_plane& plane = patch_plane_[p * transform_count_ + i];
    plane.normal = i == 0 ? proxies_[p].normal : reflect_vector(settings_.planes[i - 1], proxies_[p].normal);
    plane.center = i == 0 ? proxies_[p].center : settings_.planes[i - 1].reflect(proxies_[p].center);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::resize_labels()
{
  patch_plane_.resize(proxies_.size() * transform_count_);
  patch_area_.resize(proxies_.size() * transform_count_, 0.);
  closed_.resize(proxies_.size() * transform_count_, 0);
  for(std::size_t p = 0; p < proxies_.size(); ++p) update_patch_planes(p);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Symmetric_partition::can_join(std::size_t f, std::size_t label) const
{
  if(closed_[label]) return false;
  return patch_face_count_[label] == 0 || next_to(f, label);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::assign(std::size_t f, std::size_t label)
{
  joins_.clear();
  joins_.push_back({0., std::uint32_t(f), std::uint32_t(label)});
  while(!joins_.empty()) {
    const Candidate c = joins_.back();
    joins_.pop_back();
    if(label_[c.face] != none) continue;
    label_[c.face] = c.label;
    ++patch_face_count_[c.label];
    queue_neighbours(c.face, c.label);
    offer_mirrors(c.face, c.label);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::queue_neighbours(std::size_t g, std::size_t l)
{
  const std::size_t i = l % transform_count_;
  for(int h = 0; h < 3; ++h) {
    const std::size_t n = neighbor_[3 * g + h];
    if(n == none || label_[n] != none) continue;
    // A patch of the identity or of plane j does not cross plane j where the face has a mirror.
    if(edge_planes_[3 * g + h] & mirror_planes_[g] & (i == 0 ? ~std::uint64_t(0) : std::uint64_t(1) << (i - 1)))
      continue;
    // An entry that cannot beat one already queued for the face is left out (every queued
    // entry succeeds if its face is still free when popped: patches only grow).
    const double en = error(n, l);
    if(en > best_queued_error_[n]) continue;
    best_queued_error_[n] = en;
    queue_.push({en, std::uint32_t(n), std::uint32_t(l)});
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::offer_mirrors(std::size_t g, std::size_t l)
{
  const std::size_t p = l / transform_count_, i = l % transform_count_;
  double e = -1.;
  for(std::size_t j = 0; j < plane_count_; ++j) {
    if(i != 0 && i != j + 1) continue;
    const std::size_t mf = mirror_face(g, j);
    if(mf == none || label_[mf] != none) continue;
    const std::size_t ml = p * transform_count_ + (i == 0 ? j + 1 : 0);
    // Not next to its patch yet: it will be offered again when a face next to it is mirrored there.
    if(!can_join(mf, ml)) continue;
    const double me = error(mf, ml);
    if(e < 0.) e = error(g, l);
    if(fits_about_as_well(mf, me, e))
      joins_.push_back({me, std::uint32_t(mf), std::uint32_t(ml)});
    else if(me <= best_queued_error_[mf]) {
      best_queued_error_[mf] = me;
      queue_.push({me, std::uint32_t(mf), std::uint32_t(ml)});
    }
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::flood()
{
  for(std::size_t popped = 0; !queue_.empty(); ++popped) {
    if(popped % sequential_items_per_report == 0) poll_progress();
    const Candidate c = queue_.top();
    queue_.pop();
    if(label_[c.face] == none && can_join(c.face, c.label)) assign(c.face, c.label);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::flood_from_seeds()
{
  const std::size_t nf = mesh_.number_of_faces();
  label_.assign(nf, none);
  best_queued_error_.assign(nf, std::numeric_limits<double>::infinity());
  patch_face_count_.assign(proxies_.size() * transform_count_, 0);
  for(const Proxy& p : proxies_)
    if(p.seed != none && label_[p.seed] == none) assign(p.seed, p.seed_label);
  flood();
  // Faces no seed reached (a component whose seeds were taken by mirrors): proxies left
  // without a face are seeded there first, then the rest join a neighbouring patch.
  std::size_t next = 0;
  for(std::size_t p = 0; p < proxies_.size(); ++p) {
    bool empty = true;
    for(std::size_t i = 0; i < transform_count_ && empty; ++i) empty = patch_face_count_[p * transform_count_ + i] == 0;
    if(!empty) continue;
    while(next < nf && label_[next] != none) ++next;
    if(next == nf) break;
    proxies_[p].normal = mesh_.normal[next].squaredNorm() > 0. ? mesh_.normal[next] : Eigen::Vector3d::UnitZ();
    proxies_[p].center = mesh_.centroid[next];
    update_patch_planes(p);
    assign(next, p * transform_count_);
    flood();
  }
  join_neighbouring_patches();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::fit_planes()
{
  for(Proxy& p : proxies_) {
    p.area = p.squares = 0.;
    p.normals = p.centers = Eigen::Vector3d::Zero();
  }
  for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f) {
    Proxy& p = proxies_[label_[f] / transform_count_];
    const std::size_t i = label_[f] % transform_count_;
    const double a = mesh_.area[f];
    const Eigen::Vector3d c = frame_centroid(f, i);
    p.area += a;
    p.normals += a * frame_normal(f, i);
    p.centers += a * c;
    p.squares += a * c.squaredNorm();
  }
  for(std::size_t q = 0; q < proxies_.size(); ++q) {
    Proxy& p = proxies_[q];
    if(p.normals.squaredNorm() > 0.) p.normal = p.normals.normalized();
    if(p.area > 0.) p.center = p.centers / p.area;
    p.error = 0.;
    p.seed = none;
    update_patch_planes(q);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Symmetric_partition::close_small_patches()
{
  for(std::size_t q = 0; q < proxies_.size(); ++q) {
    double largest = 0.;
    for(std::size_t i = 0; i < transform_count_; ++i) largest = (std::max)(largest, patch_area_[q * transform_count_ + i]);
    for(std::size_t i = 0; i < transform_count_; ++i) {
      const std::size_t l = q * transform_count_ + i;
      closed_[l] = patch_area_[l] > 0. && patch_area_[l] < closed_patch_fraction * largest && l != proxies_[q].seed_label;
    }
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Symmetric_partition::moment_error(double area, const Eigen::Vector3d& normals, const Eigen::Vector3d& centers, double squares) const
{
  if(!(area > 0.)) return 0.;
  return normal_weight_ * (2. * area - 2. * normals.norm()) + position_weight_ * (squares - centers.squaredNorm() / area);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Symmetric_partition::Merge Symmetric_partition::cheapest_merge(std::size_t worst) const
{
  Merge best{none, none, 0.};
  for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f)
    for(int h = 0; h < 3; ++h) {
      const std::size_t n = mesh_.neighbor(3 * f + h);
      if(n == none) continue;
      const std::size_t p = label_[f] / transform_count_, q = label_[n] / transform_count_;
      if(p >= q || p == worst || q == worst) continue;
      const Proxy &x = proxies_[p], &y = proxies_[q];
      const double change =
        moment_error(x.area + y.area, x.normals + y.normals, x.centers + y.centers, x.squares + y.squares) -
        moment_error(x.area, x.normals, x.centers, x.squares) - moment_error(y.area, y.normals, y.centers, y.squares);
      if(best.first == none || change < best.cost) best = {p, q, change};
    }
  return best;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PARTITION_H
