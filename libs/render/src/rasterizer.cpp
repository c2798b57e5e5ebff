#include "rasterizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace vsl::render {
namespace {

// Screen-space plane of 1/z over the triangle: 1/z = a u + b v + c. Taken from the triangle's
// exact 3D plane rather than interpolated from projected vertices, so that depth is exact to
// float precision and the same for the pieces a near-plane clip makes.
struct InverseDepthPlane {
  double a = 0.0, b = 0.0, c = 0.0;
};

class TriangleRasterizer {
 public:
  explicit TriangleRasterizer(const RasterTarget& target) : target_(target) {}

  void draw(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
            const InverseDepthPlane& plane, std::int32_t triangle_index) const {
    std::array<Edge, 3> edges;
    if (!make_edge(p0, p1, p2, edges[0]) || !make_edge(p1, p2, p0, edges[1]) ||
        !make_edge(p2, p0, p1, edges[2])) {
      return;  // zero area
    }
    const double min_y = std::min({p0.y(), p1.y(), p2.y()});
    const double max_y = std::max({p0.y(), p1.y(), p2.y()});
    const int row_begin = static_cast<int>(std::max(0.0, std::ceil(min_y)));
    const int row_end =
        static_cast<int>(std::min(static_cast<double>(target_.height_px - 1), std::floor(max_y)));
    const double last_column = target_.width_px - 1;
    const auto a = static_cast<float>(plane.a);
    for (int row = row_begin; row <= row_end; ++row) {
      // The row's span where all three edge functions pass: one interval, found per edge from
      // its root instead of testing every pixel of the bounding box.
      double lo = 0.0;
      double hi = last_column;
      bool empty = false;
      for (const Edge& edge : edges) {
        const double s = edge.b * row + edge.c;
        if (edge.a > 0.0) {
          lo = std::max(lo, std::ceil(-s * edge.inverse_a));  // a x + s >= 0 (this edge owns ties)
        } else if (edge.a < 0.0) {
          hi = std::min(hi, std::ceil(-s * edge.inverse_a) - 1.0);  // a x + s > 0 (neighbour's)
        } else if (edge.b > 0.0 ? s < 0.0 : s <= 0.0) {
          empty = true;  // horizontal edge: the whole row is out
        }
      }
      if (empty || lo > hi) continue;
      const int first = static_cast<int>(lo);
      const int last = static_cast<int>(hi);
      const std::size_t offset = static_cast<std::size_t>(row) * target_.width_px;
      float* __restrict inverse_depth = target_.inverse_depth + offset;
      std::int32_t* __restrict triangle = target_.triangle + offset;
      const auto row_base = static_cast<float>(plane.b * row + plane.c);
      // Branch-free depth test: the compiler vectorizes it, and a mispredicted branch per pixel
      // cost more than the stores it saves.
      for (int column = first; column <= last; ++column) {
        const float value = row_base + a * static_cast<float>(column);
        const float old = inverse_depth[column];
        const std::int32_t nearer = -static_cast<std::int32_t>(old < value);  // all ones or zero
        inverse_depth[column] = old < value ? value : old;
        triangle[column] = (triangle_index & nearer) | (triangle[column] & ~nearer);
      }
    }
  }

 private:
  // Edge function e(x, y) = a x + b y + c, positive inside the triangle.
  struct Edge {
    double a = 0.0, b = 0.0, c = 0.0;
    double inverse_a = 0.0;  // 1 / a, exactly negated with a: shared edges still agree
  };

  // Coefficients are computed from the edge's endpoints in a canonical order and only then
  // negated toward the inside: the two triangles sharing an edge get exactly opposite functions,
  // so the tie rule gives every pixel on the edge to exactly one of them (no cracks, no overlap).
  static bool make_edge(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                        const Eigen::Vector2d& opposite, Edge& edge) {
    const bool ordered = from.x() < to.x() || (from.x() == to.x() && from.y() <= to.y());
    const Eigen::Vector2d& l = ordered ? from : to;
    const Eigen::Vector2d& u = ordered ? to : from;
    edge.a = l.y() - u.y();
    edge.b = u.x() - l.x();
    edge.c = l.x() * u.y() - u.x() * l.y();
    const double side = edge.a * opposite.x() + edge.b * opposite.y() + edge.c;
    if (!(side != 0.0)) return false;
    if (side < 0.0) {
      edge.a = -edge.a;
      edge.b = -edge.b;
      edge.c = -edge.c;
    }
    edge.inverse_a = edge.a != 0.0 ? 1.0 / edge.a : 0.0;
    return true;
  }

  RasterTarget target_;
};

// Bits of the frustum half-spaces a camera-frame point is outside of.
enum Outside : unsigned {
  kNear = 1,
  kFar = 2,
  kLeft = 4,
  kRight = 8,
  kTop = 16,
  kBottom = 32,
};

// The pinhole camera's projection and its view frustum, in the camera frame.
struct Frustum {
  Frustum(const Pinhole& camera, double near_m, double far_m)
      : fx(camera.fx_px),
        fy(camera.fy_px),
        cx(camera.cx_px),
        cy(camera.cy_px),
        near_clip_m(near_m),
        far_clip_m(far_m),
        right_edge(camera.width_px - 0.5),
        bottom_edge(camera.height_px - 0.5) {}

  // The side planes pass through the camera centre at the image's outer pixel edges, as
  // half-spaces k . p >= 0.
  unsigned outside(const Eigen::Vector3d& p) const {
    unsigned code = 0;
    if (p.z() < near_clip_m) code |= kNear;
    if (p.z() > far_clip_m) code |= kFar;
    if (fx * p.x() + (cx - left_edge) * p.z() < 0.0) code |= kLeft;
    if (fx * p.x() + (cx - right_edge) * p.z() > 0.0) code |= kRight;
    if (fy * p.y() + (cy - top_edge) * p.z() < 0.0) code |= kTop;
    if (fy * p.y() + (cy - bottom_edge) * p.z() > 0.0) code |= kBottom;
    return code;
  }
  Eigen::Vector2d project(const Eigen::Vector3d& p) const {
    return Eigen::Vector2d(fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy);
  }

  double fx, fy, cx, cy;
  double near_clip_m, far_clip_m;
  double left_edge = -0.5, right_edge, top_edge = -0.5, bottom_edge;
};

// A triangle that crosses the near plane, clipped against it (Sutherland-Hodgman: 3 corners
// give at most 4) and drawn. A crossing point is always interpolated from the inside corner
// toward the outside one, so that the two triangles sharing a clipped edge get the same point.
void draw_near_clipped(const TriangleRasterizer& rasterizer, const Frustum& frustum,
                       const std::array<std::uint32_t, 3>& corners,
                       const std::vector<Eigen::Vector3d>& camera_vertices,
                       const std::vector<Eigen::Vector2d>& pixel_vertices,
                       const InverseDepthPlane& plane, std::int32_t index) {
  std::array<Eigen::Vector2d, 4> polygon;
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& current = camera_vertices[corners[i]];
    const Eigen::Vector3d& next = camera_vertices[corners[(i + 1) % 3]];
    const bool current_in = current.z() >= frustum.near_clip_m;
    const bool next_in = next.z() >= frustum.near_clip_m;
    if (current_in) polygon[count++] = pixel_vertices[corners[i]];
    if (current_in != next_in) {
      const Eigen::Vector3d& in = current_in ? current : next;
      const Eigen::Vector3d& out = current_in ? next : current;
      const double s = (frustum.near_clip_m - in.z()) / (out.z() - in.z());
      polygon[count++] = frustum.project(in + s * (out - in));
    }
  }
  for (int i = 1; i + 1 < count; ++i) {
    rasterizer.draw(polygon[0], polygon[i], polygon[i + 1], plane, index);
  }
}

// The Frustum bits a chunk's bounding box lies wholly outside of (all_outside) and partly
// outside of (any_outside).
std::pair<unsigned, unsigned> chunk_outside(const Chunk& chunk, const Frustum& frustum,
                                            const Eigen::Matrix3d& camera_R_world,
                                            const Eigen::Vector3d& camera_t_world) {
  unsigned all_outside = ~0u;
  unsigned any_outside = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d world_corner(
        (corner & 1) ? chunk.world_max_m.x() : chunk.world_min_m.x(),
        (corner & 2) ? chunk.world_max_m.y() : chunk.world_min_m.y(),
        (corner & 4) ? chunk.world_max_m.z() : chunk.world_min_m.z());
    const unsigned code = frustum.outside(camera_R_world * world_corner + camera_t_world);
    all_outside &= code;
    any_outside |= code;
  }
  return {all_outside, any_outside};
}

}  // namespace

void rasterize(const Scene& scene, const Pinhole& camera, const Eigen::Isometry3d& world_T_camera,
               double near_clip_m, double far_clip_m, const RasterTarget& target) {
  const auto pixels = static_cast<std::size_t>(target.width_px) * target.height_px;
  // Initialising to 1/far makes the depth test clip at the far distance for free.
  std::fill_n(target.inverse_depth, pixels, static_cast<float>(1.0 / far_clip_m));
  std::fill_n(target.triangle, pixels, -1);
  if (pixels == 0) return;

  const Eigen::Matrix3d camera_R_world = world_T_camera.linear().transpose();
  const Eigen::Vector3d world_camera_position = world_T_camera.translation();
  const Eigen::Vector3d camera_t_world = -camera_R_world * world_camera_position;
  const Frustum frustum(camera, near_clip_m, far_clip_m);
  const double fx = frustum.fx, fy = frustum.fy, cx = frustum.cx, cy = frustum.cy;

  // Per chunk scratch, indexed by vertex - chunk.first_vertex: small enough to stay in L1.
  std::vector<Eigen::Vector3d> camera_vertices(scene.max_chunk_vertices);
  std::vector<Eigen::Vector2d> pixel_vertices(scene.max_chunk_vertices);
  const TriangleRasterizer rasterizer(target);

  for (const Chunk& chunk : scene.chunks) {
    const auto [all_outside, any_outside] =
        chunk_outside(chunk, frustum, camera_R_world, camera_t_world);
    if (all_outside != 0) continue;  // wholly outside one plane of the frustum
    const bool crosses_near = (any_outside & kNear) != 0;

    for (std::uint32_t v = 0; v < chunk.vertex_count; ++v) {
      camera_vertices[v] =
          camera_R_world * scene.world_vertices_m[chunk.first_vertex + v] + camera_t_world;
      if (camera_vertices[v].z() >= near_clip_m) {
        pixel_vertices[v] = frustum.project(camera_vertices[v]);
      }
    }

    const std::uint32_t triangle_end = chunk.first_triangle + chunk.triangle_count;
    for (std::uint32_t t = chunk.first_triangle; t < triangle_end; ++t) {
      const Eigen::Vector4d& world_plane = scene.world_planes[t];
      const Eigen::Vector3d world_normal = world_plane.head<3>();
      // Plane in the camera frame: n_c . p = d_c. The camera (origin) is on the outer side of a
      // front face, so d_c < 0; cull back faces and faces seen edge-on.
      const double camera_d = world_plane.w() - world_normal.dot(world_camera_position);
      if (camera_d > -1e-9) continue;
      const Eigen::Vector3d camera_normal = camera_R_world * world_normal;
      InverseDepthPlane plane;
      plane.a = camera_normal.x() / (fx * camera_d);
      plane.b = camera_normal.y() / (fy * camera_d);
      plane.c = (camera_normal.z() - camera_normal.x() * cx / fx - camera_normal.y() * cy / fy) /
                camera_d;

      const auto& global = scene.triangles[t];
      const std::array<std::uint32_t, 3> corners{global[0] - chunk.first_vertex,
                                                 global[1] - chunk.first_vertex,
                                                 global[2] - chunk.first_vertex};
      const auto index = static_cast<std::int32_t>(t);
      const bool in_front = !crosses_near || (camera_vertices[corners[0]].z() >= near_clip_m &&
                                              camera_vertices[corners[1]].z() >= near_clip_m &&
                                              camera_vertices[corners[2]].z() >= near_clip_m);
      if (in_front) {
        rasterizer.draw(pixel_vertices[corners[0]], pixel_vertices[corners[1]],
                        pixel_vertices[corners[2]], plane, index);
      } else {
        draw_near_clipped(rasterizer, frustum, corners, camera_vertices, pixel_vertices, plane,
                          index);
      }
    }
  }
}

}  // namespace vsl::render
