// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PARTITION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PARTITION_H

// Symmetric proxy generation (thesis, Section 5.1.2): Lloyd iterations of Variational Shape
// Approximation where a proxy is a plane with up to one connected patch per transform (the
// identity and the reflection through each plane). A patch is labelled
// `proxy * transforms + transform` (transform 0: the identity, j + 1: plane j).
//
// Flooding: one priority queue, in increasing error, as in VSA; when a face joins a patch, its
// neighbours are queued for that patch and the face nearest to its mirror image (a Kd-tree
// query made once) is offered to the mirrored patch. The mirror joins at once if it fits that
// patch about as well as the face fits its own (on an exactly symmetric mesh it always does, so
// that the partition stays mirror-symmetric whatever the order of equal errors), else it is
// queued with its own error and competes as any face. A patch stays connected: a face only joins
// a non-empty patch next to one of its faces. Where a face has a mirror through a plane, a patch
// of the identity or of that plane does not grow across the plane: its mirrored patch takes over
// there, so that a proxy spanning the plane is cut along it into two mirrored patches.
//
// Mirror-consistent boundaries, after the last iteration: the flooding order decides where a
// boundary runs on each side of a plane, so on a nearly symmetric mesh the two sides' boundaries,
// and the junctions where the output's anchors go, still differ by a face here and there. A face
// on the negative side of a plane then takes the mirror of its mirror face's patch, if it lies
// next to that patch and fits it about as well as its own (the flooding's rule); a patch cut in
// pieces by this keeps its largest piece and gives the others to neighbouring patches.
//
// Metric (thesis, "Error Metric"): E(t, P) = a_t (alpha |c_t - c_P|^2 / A_avg + (1 - alpha)
// |n_t - n_P|^2), with c and n centroids and unit normals, P's parameters moved by the patch's
// transform, a_t the area of t and A_avg the mean face area: the area-weighted form of the
// thesis's metric, which is L2,1 (CGAL's default) for alpha = 0.

#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>

#include <CGAL/Random.h>
#include <CGAL/Variational_shape_approximation.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

struct Remeshing_settings
{
  std::vector<Dplane> planes;
  double position_weight = 0.;        // alpha
  bool strongest_plane_only = false;
  std::size_t max_number_of_proxies = 0;
  double min_error_drop = 0.;
  std::size_t number_of_iterations = 20, number_of_relaxations = 5;
  Surface_mesh_approximation::Seeding_method seeding = Surface_mesh_approximation::HIERARCHICAL;
  unsigned random_seed = 0;
  unsigned threads = 1;
  bool verbose = false;
};

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

  Symmetric_partition(const Remeshing_mesh& mesh, const Remeshing_settings& settings,
                      const std::vector<std::size_t>& mirror, const std::vector<std::uint64_t>& vertex_planes)
    : m_(mesh), s_(settings), mirror_(mirror), vertex_planes_(vertex_planes), k_(settings.planes.size()),
      t_(k_ + 1)
  {
    double total = 0.;
    for(double a : m_.area) total += a;
    const double average_area = total / double(m_.number_of_faces());
    wn_ = 1. - s_.position_weight;
    wp_ = average_area > 0. ? s_.position_weight / average_area : 0.;
    label_.assign(m_.number_of_faces(), none);
    // The data the flooding reads, packed per face (one cache line) for speed.
    face_.resize(m_.number_of_faces());
    neighbor_.resize(3 * m_.number_of_faces());
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      Face_data& d = face_[f];
      for(int i = 0; i < 3; ++i) {
        d.n[i] = m_.normal[f][i];
        d.c[i] = m_.centroid[f][i];
        neighbor_[3 * f + i] = m_.neighbor(3 * f + i);
      }
      d.a = m_.area[f];
    }
    // Per halfedge the planes it lies on, per face the planes through which it has a mirror.
    edge_planes_.assign(3 * m_.number_of_faces(), 0);
    mirror_planes_.assign(m_.number_of_faces(), 0);
    for(std::size_t h = 0; h < edge_planes_.size(); ++h)
      edge_planes_[h] = vertex_planes_[m_.source(h)] & vertex_planes_[m_.target(h)];
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f)
      for(std::size_t j = 0; j < k_; ++j)
        if(mirror_[f * k_ + j] != none) mirror_planes_[f] |= std::uint64_t(1) << j;
  }

  std::size_t transforms() const { return t_; }
  const std::vector<std::size_t>& labels() const { return label_; }
  const std::vector<Proxy>& proxies() const { return proxies_; }
  std::size_t proxy_of(std::size_t label) const { return label / t_; }

  // The plane of a patch: the proxy's, moved by the patch's transform.
  const Eigen::Vector3d& patch_normal(std::size_t label) const { return tn_[label]; }
  const Eigen::Vector3d& patch_center(std::size_t label) const { return tc_[label]; }
  double patch_area(std::size_t label) const { return patch_area_[label]; }

  double total_error() const
  {
    double e = 0.;
    for(const Proxy& p : proxies_) e += p.error;
    return e;
  }

  // Seeding as CGAL's VSA (initialize_seeds), then `number_of_iterations` iterations with a
  // teleportation attempt after each `number_of_relaxations` of them.
  void run()
  {
    std::size_t max_proxies = s_.max_number_of_proxies;
    double min_drop = s_.min_error_drop;
    const std::size_t nf = m_.number_of_faces();
    if(max_proxies < nf / 3 && max_proxies > 0) {
      if(!(min_drop < 1.) || !(min_drop > 0.)) min_drop = -1.;
    } else {
      max_proxies = nf / 3;
      if(!(min_drop < 1.) || !(min_drop > 0.)) min_drop = 0.1;
    }
    bootstrap();
    if(proxies_.size() < max_proxies) {
      if(s_.seeding == Surface_mesh_approximation::RANDOM) seed_random(max_proxies);
      else if(s_.seeding == Surface_mesh_approximation::INCREMENTAL) seed_incremental(max_proxies, min_drop);
      else seed_hierarchical(max_proxies, min_drop);
    }
    if(s_.verbose) std::cerr << "  seeding: " << proxies_.size() << " proxies, error " << total_error() << "\n";
    const std::size_t relax = (std::max<std::size_t>)(1, s_.number_of_relaxations);
    for(std::size_t i = 0; i < s_.number_of_iterations; ++i) {
      if(i > 0 && i % relax == 0) teleport();
      iterate();
    }
    if(s_.verbose) std::cerr << "  " << s_.number_of_iterations << " iterations: error " << total_error() << "\n";
    if(k_ > 0 && mirror_boundaries() > 0) {
      reconnect_patches();
      fit();
    }
  }

private:
  struct Candidate
  {
    double error;
    std::uint32_t face, label;
    bool operator>(const Candidate& c) const
    {
      return error > c.error || (error == c.error && key() > c.key());
    }
    std::uint64_t key() const { return (std::uint64_t(face) << 32) | label; }
  };

  // Face data of face f in the frame of transform i.
  Eigen::Vector3d frame_normal(std::size_t f, std::size_t i) const
  {
    return i == 0 ? m_.normal[f] : reflect_vector(s_.planes[i - 1], m_.normal[f]);
  }
  Eigen::Vector3d frame_centroid(std::size_t f, std::size_t i) const
  {
    return i == 0 ? m_.centroid[f] : s_.planes[i - 1].reflect(m_.centroid[f]);
  }

  double error(std::size_t f, std::size_t label) const
  {
    const Face_data& d = face_[f];
    const Target& t = target_[label];
    double n2 = 0., c2 = 0.;
    for(int i = 0; i < 3; ++i) n2 += (d.n[i] - t.n[i]) * (d.n[i] - t.n[i]);
    if(wp_ > 0.)
      for(int i = 0; i < 3; ++i) c2 += (d.c[i] - t.c[i]) * (d.c[i] - t.c[i]);
    return d.a * (wn_ * n2 + wp_ * c2);
  }

  void update_targets(std::size_t p)
  {
    for(std::size_t i = 0; i < t_; ++i) {
      const std::size_t l = p * t_ + i;
      tn_[l] = i == 0 ? proxies_[p].normal : reflect_vector(s_.planes[i - 1], proxies_[p].normal);
      tc_[l] = i == 0 ? proxies_[p].center : s_.planes[i - 1].reflect(proxies_[p].center);
      for(int c = 0; c < 3; ++c) {
        target_[l].n[c] = tn_[l][c];
        target_[l].c[c] = tc_[l][c];
      }
    }
  }

  void resize_labels()
  {
    tn_.resize(proxies_.size() * t_);
    tc_.resize(proxies_.size() * t_);
    target_.resize(proxies_.size() * t_);
    patch_area_.resize(proxies_.size() * t_, 0.);
    disabled_.resize(proxies_.size() * t_, 0);
    for(std::size_t p = 0; p < proxies_.size(); ++p) update_targets(p);
  }

  std::size_t add_proxy_at(std::size_t f)
  {
    Proxy p;
    p.normal = m_.normal[f].squaredNorm() > 0. ? m_.normal[f] : Eigen::Vector3d::UnitZ();
    p.center = m_.centroid[f];
    p.seed = f;
    p.seed_label = proxies_.size() * t_;
    proxies_.push_back(p);
    resize_labels();
    return proxies_.size() - 1;
  }

  bool can_join(std::size_t f, std::size_t label) const
  {
    if(disabled_[label]) return false;
    return patch_faces_[label] == 0 || next_to(f, label);
  }

  // Whether an error `e` of face f for a mirrored patch is about that of the face it mirrors
  // (`reference`): on an exactly symmetric mesh it always is.
  bool fits_about_as_well(std::size_t f, double e, double reference) const
  {
    return e <= 2. * reference + 0.01 * face_[f].a;
  }

  void assign(std::size_t f, std::size_t label)
  {
    stack_.clear();
    stack_.push_back({0., std::uint32_t(f), std::uint32_t(label)});
    while(!stack_.empty()) {
      const Candidate c = stack_.back();
      stack_.pop_back();
      const std::size_t g = c.face, l = c.label;
      if(label_[g] != none) continue;
      label_[g] = l;
      ++patch_faces_[l];
      const std::size_t p = l / t_, i = l % t_;
      double e = -1.;
      for(int h = 0; h < 3; ++h) {
        const std::size_t n = neighbor_[3 * g + h];
        if(n == none || label_[n] != none) continue;
        // A patch of the identity or of plane j does not cross plane j where the face has a mirror.
        if(edge_planes_[3 * g + h] & mirror_planes_[g] & (i == 0 ? ~std::uint64_t(0) : std::uint64_t(1) << (i - 1)))
          continue;
        // An entry that cannot beat one already queued for the face is left out (every queued
        // entry succeeds if its face is still free when popped: patches only grow).
        const double en = error(n, l);
        if(en > best_[n]) continue;
        best_[n] = en;
        heap_.push({en, std::uint32_t(n), std::uint32_t(l)});
      }
      for(std::size_t j = 0; j < k_; ++j) {
        if(i != 0 && i != j + 1) continue; // reflections of the identity patch, and back to it
        const std::size_t mf = mirror_[g * k_ + j];
        if(mf == none || label_[mf] != none) continue;
        const std::size_t ml = p * t_ + (i == 0 ? j + 1 : 0);
        // Not next to its patch yet: it will be offered again when a face next to it is mirrored there.
        if(!can_join(mf, ml)) continue;
        const double me = error(mf, ml);
        if(e < 0.) e = error(g, l);
        if(fits_about_as_well(mf, me, e))
          stack_.push_back({me, std::uint32_t(mf), std::uint32_t(ml)});
        else if(me <= best_[mf]) {
          best_[mf] = me;
          heap_.push({me, std::uint32_t(mf), std::uint32_t(ml)});
        }
      }
    }
  }

  void partition()
  {
    const std::size_t nf = m_.number_of_faces();
    label_.assign(nf, none);
    best_.assign(nf, std::numeric_limits<double>::infinity());
    patch_faces_.assign(proxies_.size() * t_, 0);
    for(const Proxy& p : proxies_)
      if(p.seed != none && label_[p.seed] == none) assign(p.seed, p.seed_label);
    auto flood = [&] {
      while(!heap_.empty()) {
        const Candidate c = heap_.top();
        heap_.pop();
        if(label_[c.face] == none && can_join(c.face, c.label)) assign(c.face, c.label);
      }
    };
    flood();
    // Faces no seed reached (a component whose seeds were taken by mirrors): proxies left
    // without a face are seeded there first, then the rest join a neighbouring patch.
    std::size_t next = 0;
    for(std::size_t p = 0; p < proxies_.size(); ++p) {
      bool empty = true;
      for(std::size_t i = 0; i < t_ && empty; ++i) empty = patch_faces_[p * t_ + i] == 0;
      if(!empty) continue;
      while(next < nf && label_[next] != none) ++next;
      if(next == nf) break;
      proxies_[p].normal = m_.normal[next].squaredNorm() > 0. ? m_.normal[next] : Eigen::Vector3d::UnitZ();
      proxies_[p].center = m_.centroid[next];
      update_targets(p);
      assign(next, p * t_);
      flood();
    }
    join_neighbouring_patches();
  }

  // Unlabelled faces join a neighbouring patch (those of a component with none, patch 0).
  void join_neighbouring_patches()
  {
    const std::size_t nf = m_.number_of_faces();
    for(bool changed = true; changed;) {
      changed = false;
      for(std::size_t f = 0; f < nf; ++f) {
        if(label_[f] != none) continue;
        for(int h = 0; h < 3 && label_[f] == none; ++h) {
          const std::size_t n = m_.neighbor(3 * f + h);
          if(n != none && label_[n] != none) {
            label_[f] = label_[n];
            ++patch_faces_[label_[f]];
            changed = true;
          }
        }
      }
    }
    for(std::size_t f = 0; f < nf; ++f)
      if(label_[f] == none) {
        label_[f] = 0;
        ++patch_faces_[0];
      }
  }

  // Faces of the negative side of each plane relabelled after their mirror faces (see the top
  // of the file), in sweeps until none changes; returns how many changed. A face does not join a
  // patch across the plane, as in the flooding.
  std::size_t mirror_boundaries()
  {
    const std::size_t nf = m_.number_of_faces();
    std::size_t changed = 0;
    for(std::size_t j = 0; j < k_; ++j)
      for(std::size_t sweep = 0, before = ~std::size_t(0); sweep < 10 && changed != before; ++sweep) {
        before = changed;
        for(std::size_t f = 0; f < nf; ++f) {
          const std::size_t mf = mirror_[f * k_ + j];
          if(mf == none || signed_distance(s_.planes[j], m_.centroid[f]) >= 0.) continue;
          const std::size_t ml = label_[mf], i = ml % t_;
          if(i != 0 && i != j + 1) continue;
          const std::size_t target = ml - i + (i == 0 ? j + 1 : 0);
          if(label_[f] == target || disabled_[target] || !next_to(f, target, std::uint64_t(1) << j) ||
             !fits_about_as_well(f, error(f, target), error(f, label_[f])))
            continue;
          --patch_faces_[label_[f]];
          label_[f] = target;
          ++patch_faces_[target];
          ++changed;
        }
      }
    return changed;
  }

  // Whether face f shares an edge with the patch, not counting edges on the planes of
  // `not_across` (a bit per plane).
  bool next_to(std::size_t f, std::size_t label, std::uint64_t not_across = 0) const
  {
    for(int i = 0; i < 3; ++i) {
      const std::size_t g = neighbor_[3 * f + i];
      if(g != none && label_[g] == label && !(edge_planes_[3 * f + i] & not_across)) return true;
    }
    return false;
  }

  // Each patch connected: the faces of all but its largest piece join neighbouring patches.
  void reconnect_patches()
  {
    const std::size_t nf = m_.number_of_faces();
    std::vector<std::size_t> piece(nf, none), stack;
    std::vector<double> piece_area;
    for(std::size_t f = 0; f < nf; ++f) {
      if(piece[f] != none) continue;
      piece[f] = piece_area.size();
      piece_area.push_back(0.);
      stack.assign(1, f);
      while(!stack.empty()) {
        const std::size_t g = stack.back();
        stack.pop_back();
        piece_area.back() += m_.area[g];
        for(int h = 0; h < 3; ++h) {
          const std::size_t n = neighbor_[3 * g + h];
          if(n != none && piece[n] == none && label_[n] == label_[g]) {
            piece[n] = piece[f];
            stack.push_back(n);
          }
        }
      }
    }
    std::vector<std::size_t> largest(proxies_.size() * t_, none);
    for(std::size_t f = 0; f < nf; ++f) {
      std::size_t& l = largest[label_[f]];
      if(l == none || piece_area[piece[f]] > piece_area[l]) l = piece[f];
    }
    for(std::size_t f = 0; f < nf; ++f)
      if(piece[f] != largest[label_[f]]) {
        --patch_faces_[label_[f]];
        label_[f] = none;
      }
    join_neighbouring_patches();
  }

  // Proxy parameters from their faces (area-weighted normal and centroid in the identity frame),
  // then errors, seeds (the best face of each proxy) and patch areas. A patch much smaller than
  // its proxy's largest is closed for the next partition (patch teleportation): its faces go
  // to other patches, and the proxy may grow it again afterwards.
  void fit()
  {
    const std::size_t np = proxies_.size();
    for(Proxy& p : proxies_) {
      p.area = p.squares = 0.;
      p.normals = p.centers = Eigen::Vector3d::Zero();
    }
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      Proxy& p = proxies_[label_[f] / t_];
      const std::size_t i = label_[f] % t_;
      const double a = m_.area[f];
      const Eigen::Vector3d c = frame_centroid(f, i);
      p.area += a;
      p.normals += a * frame_normal(f, i);
      p.centers += a * c;
      p.squares += a * c.squaredNorm();
    }
    for(std::size_t q = 0; q < np; ++q) {
      Proxy& p = proxies_[q];
      if(p.normals.squaredNorm() > 0.) p.normal = p.normals.normalized();
      if(p.area > 0.) p.center = p.centers / p.area;
      p.error = 0.;
      p.seed = none;
      update_targets(q);
    }
    std::fill(patch_area_.begin(), patch_area_.end(), 0.);
    std::vector<double> best(np, 0.);
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const std::size_t l = label_[f];
      Proxy& p = proxies_[l / t_];
      const double e = error(f, l);
      p.error += e;
      patch_area_[l] += m_.area[f];
      if(p.seed == none || e < best[l / t_]) {
        p.seed = f;
        p.seed_label = l;
        best[l / t_] = e;
      }
    }
    for(std::size_t q = 0; q < np; ++q) {
      double largest = 0.;
      for(std::size_t i = 0; i < t_; ++i) largest = (std::max)(largest, patch_area_[q * t_ + i]);
      for(std::size_t i = 0; i < t_; ++i) {
        const std::size_t l = q * t_ + i;
        disabled_[l] = patch_area_[l] > 0. && patch_area_[l] < 0.05 * largest && l != proxies_[q].seed_label;
      }
    }
  }

  double iterate()
  {
    partition();
    fit();
    return total_error();
  }

  double run_iterations(std::size_t count)
  {
    double e = total_error();
    for(std::size_t i = 0; i < count; ++i) e = iterate();
    return e;
  }

  // One proxy per connected component of the mesh.
  void bootstrap()
  {
    const std::size_t nf = m_.number_of_faces();
    std::vector<std::size_t> component(nf, none), stack;
    proxies_.clear();
    for(std::size_t f = 0; f < nf; ++f) {
      if(component[f] != none) continue;
      const std::size_t c = proxies_.size();
      add_proxy_at(f);
      component[f] = c;
      stack.assign(1, f);
      while(!stack.empty()) {
        const std::size_t g = stack.back();
        stack.pop_back();
        for(int h = 0; h < 3; ++h) {
          const std::size_t n = m_.neighbor(3 * g + h);
          if(n != none && component[n] == none) {
            component[n] = c;
            stack.push_back(n);
          }
        }
      }
    }
    for(std::size_t f = 0; f < nf; ++f) label_[f] = component[f] * t_;
    patch_faces_.assign(proxies_.size() * t_, 0);
    fit();
    std::fill(disabled_.begin(), disabled_.end(), 0);
  }

  // CGAL's error diffusion: `count` new proxies, shared among the proxies in proportion to their
  // error (to their size if all errors are zero), each placed at faces spread over its region.
  std::size_t add_proxies_by_error(std::size_t count)
  {
    const std::size_t np = proxies_.size(), nf = m_.number_of_faces();
    std::vector<std::vector<std::size_t>> region(np);
    for(std::size_t f = 0; f < nf; ++f) region[label_[f] / t_].push_back(f);
    std::vector<double> weight(np);
    double sum = 0.;
    for(std::size_t p = 0; p < np; ++p) sum += weight[p] = proxies_[p].error;
    if(!(sum > 0.)) {
      sum = 0.;
      for(std::size_t p = 0; p < np; ++p) sum += weight[p] = double(region[p].size());
    }
    std::vector<std::size_t> order(np);
    for(std::size_t p = 0; p < np; ++p) order[p] = p;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weight[a] < weight[b]; });
    const double unit = sum / double(count);
    double residual = 0.;
    std::size_t added = 0;
    for(std::size_t p : order) {
      const double share = (residual + weight[p]) / unit;
      const double rounded = std::floor(share + 0.5);
      residual = (share - rounded) * unit;
      std::size_t n = (std::min)(std::size_t((std::max)(0., rounded)), region[p].size() - 1);
      for(std::size_t q = 0; q < n; ++q) {
        const std::size_t at = std::size_t((double(q) + 0.5) * double(region[p].size()) / double(n));
        std::size_t f = region[p][at];
        if(f == proxies_[p].seed) f = region[p][(at + 1) % region[p].size()];
        add_proxy_at(f);
        ++added;
      }
    }
    return added;
  }

  void seed_hierarchical(std::size_t max_proxies, double min_drop)
  {
    const double initial = total_error();
    double drop = !(min_drop > 0.) ? 1. : 2. * min_drop;
    while(proxies_.size() < max_proxies && drop > min_drop) {
      const std::size_t target = (std::min)(2 * proxies_.size(), max_proxies);
      if(add_proxies_by_error(target - proxies_.size()) == 0) break;
      const double e = run_iterations(s_.number_of_relaxations);
      drop = initial > 0. ? e / initial : 0.;
    }
  }

  // The face of largest error of the worst proxy, other than its seed, or `none`.
  std::size_t worst_face(std::size_t* worst_proxy = nullptr) const
  {
    std::size_t worst = 0;
    for(std::size_t p = 1; p < proxies_.size(); ++p)
      if(proxies_[p].error > proxies_[worst].error) worst = p;
    std::size_t face = none;
    double largest = -1.;
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f)
      if(label_[f] / t_ == worst && f != proxies_[worst].seed) {
        const double e = error(f, label_[f]);
        if(e > largest) {
          largest = e;
          face = f;
        }
      }
    if(worst_proxy) *worst_proxy = worst;
    return face;
  }

  void seed_incremental(std::size_t max_proxies, double min_drop)
  {
    const double initial = total_error();
    double drop = !(min_drop > 0.) ? 1. : 2. * min_drop;
    while(proxies_.size() < max_proxies && drop > min_drop) {
      const std::size_t f = worst_face();
      if(f == none) break;
      add_proxy_at(f);
      const double e = run_iterations(s_.number_of_relaxations);
      drop = initial > 0. ? e / initial : 0.;
    }
  }

  void seed_random(std::size_t max_proxies)
  {
    CGAL::Random random(s_.random_seed);
    const std::size_t nf = m_.number_of_faces();
    std::vector<char> taken(nf, 0);
    for(const Proxy& p : proxies_) taken[p.seed] = 1;
    while(proxies_.size() < max_proxies) {
      const std::size_t f = std::size_t(random.get_int(0, int(nf)));
      if(taken[f]) continue;
      taken[f] = 1;
      add_proxy_at(f);
    }
    run_iterations(s_.number_of_relaxations);
  }

  // Optimal error of the moments of a set of faces (in the identity frame).
  double moment_error(double area, const Eigen::Vector3d& normals, const Eigen::Vector3d& centers, double squares) const
  {
    if(!(area > 0.)) return 0.;
    return wn_ * (2. * area - 2. * normals.norm()) + wp_ * (squares - centers.squaredNorm() / area);
  }

  // Proxy teleportation (CGAL's teleport_proxies): the adjacent pair whose merge costs least is
  // merged, and the freed proxy is moved to the worst face of the worst proxy, if the merge costs
  // less than half the worst proxy's error.
  bool teleport()
  {
    std::size_t worst = 0;
    const std::size_t target = worst_face(&worst);
    if(target == none) return false;
    double best = 0.;
    std::size_t a = none, b = none;
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f)
      for(int h = 0; h < 3; ++h) {
        const std::size_t n = m_.neighbor(3 * f + h);
        if(n == none) continue;
        std::size_t p = label_[f] / t_, q = label_[n] / t_;
        if(p >= q || p == worst || q == worst) continue;
        const Proxy &x = proxies_[p], &y = proxies_[q];
        const double change = moment_error(x.area + y.area, x.normals + y.normals, x.centers + y.centers,
                                           x.squares + y.squares) -
                              moment_error(x.area, x.normals, x.centers, x.squares) -
                              moment_error(y.area, y.normals, y.centers, y.squares);
        if(a == none || change < best) {
          best = change;
          a = p;
          b = q;
        }
      }
    if(a == none || best > proxies_[worst].error / 2.) return false;
    Proxy& x = proxies_[a];
    const Proxy& y = proxies_[b];
    x.area += y.area;
    x.normals += y.normals;
    x.centers += y.centers;
    x.squares += y.squares;
    if(x.normals.squaredNorm() > 0.) x.normal = x.normals.normalized();
    if(x.area > 0.) x.center = x.centers / x.area;
    update_targets(a);
    Proxy moved;
    moved.normal = m_.normal[target].squaredNorm() > 0. ? m_.normal[target] : Eigen::Vector3d::UnitZ();
    moved.center = m_.centroid[target];
    moved.seed = target;
    moved.seed_label = b * t_;
    proxies_[b] = moved;
    update_targets(b);
    for(std::size_t i = 0; i < t_; ++i) disabled_[b * t_ + i] = disabled_[a * t_ + i] = 0;
    return true;
  }

  const Remeshing_mesh& m_;
  const Remeshing_settings& s_;
  const std::vector<std::size_t>& mirror_;
  const std::vector<std::uint64_t>& vertex_planes_;
  const std::size_t k_, t_;
  double wn_ = 1., wp_ = 0.;
  std::vector<Proxy> proxies_;
  std::vector<std::size_t> label_, patch_faces_;
  std::vector<Eigen::Vector3d> tn_, tc_;
  struct Face_data
  {
    double n[3], c[3], a, unused;
  };
  struct Target
  {
    double n[3], c[3];
  };
  std::vector<Face_data> face_;
  std::vector<Target> target_;
  std::vector<std::size_t> neighbor_;
  std::vector<std::uint64_t> edge_planes_, mirror_planes_;
  std::vector<double> patch_area_, best_;
  std::vector<char> disabled_;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap_;
  std::vector<Candidate> stack_;
};

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PARTITION_H
