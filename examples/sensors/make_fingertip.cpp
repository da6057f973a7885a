// Generates examples/sensors/fingertip.step: a fingertip sensor's skin, drawn with Gmsh's OpenCASCADE
// kernel. The finger lies along x (tip at +x), its skin faces +z:
//   solid = cylinder (radius 9 mm, x in [-15, 0]) fused with a sphere (radius 9 mm at the origin);
//   skin  = the solid's curved outer faces with z >= 3 mm (a height field over x, y): one
//           cylindrical face and one spherical face meeting at x = 0.
// The skin's border is split at both ends of 16 electrodes (3 mm of arc each, evenly spaced around
// the border, electrode 0 centred on the tip at (sqrt(72), 0, 3), counter-clockwise seen from +z),
// so that each electrode is exactly one curve of the STEP file. Four of them would straddle a corner
// of the border (a vertex of the faces): those are slid up to 0.27 mm to end at it (electrode_spans_mm).
//
//   emit_make_fingertip [OUT.step]   write (default examples/sensors/fingertip.step), print the
//                                    electrodes' midpoints, then re-open OUT.step and check it
//   emit_make_fingertip --check FILE check FILE only
// The exit status is 0 when the check passes.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gmsh.h>

namespace occ = gmsh::model::occ;
using Point = std::array<double, 3>;

namespace {

constexpr double radius_mm = 9;    // the finger's (cylinder's and sphere's) radius
constexpr double phalanx_mm = 15;  // the cylinder's length, x in [-15, 0]
constexpr double cut_z_mm = 3;     // the skin is the surface above this height
constexpr int electrode_count = 16;
constexpr double electrode_mm = 3.0;  // each electrode's length along the border

// The border, walked counter-clockwise from +z starting at the tip's middle, in five pieces.
const double rim_mm = std::sqrt(radius_mm * radius_mm - cut_z_mm * cut_z_mm);  // sqrt(72): the border's |y|
const double back_half_rad = std::acos(cut_z_mm / radius_mm);                  // half the back arc's angle
const double tip_quarter_mm = rim_mm * std::numbers::pi / 2;                   // a quarter of the tip's circle
const double back_arc_mm = 2 * radius_mm * back_half_rad;
const double border_mm = 2 * tip_quarter_mm + 2 * phalanx_mm + back_arc_mm;  // about 78.81
// Where the border has a vertex of the skin's faces (the cylinder meets the sphere, or the back arc
// meets a straight side), by arc length from the start.
const std::array<double, 4> corners_mm = {tip_quarter_mm, tip_quarter_mm + phalanx_mm,
                                          tip_quarter_mm + phalanx_mm + back_arc_mm,
                                          tip_quarter_mm + 2 * phalanx_mm + back_arc_mm};

/// The border's point at arc length s_mm from the tip's middle, counter-clockwise from +z.
Point border_point_mm(double s_mm) {
  s_mm = std::fmod(std::fmod(s_mm, border_mm) + border_mm, border_mm);
  if (s_mm < tip_quarter_mm) {  // the tip's circle, from angle 0 to 90 degrees
    const double a_rad = s_mm / rim_mm;
    return {rim_mm * std::cos(a_rad), rim_mm * std::sin(a_rad), cut_z_mm};
  }
  if ((s_mm -= tip_quarter_mm) < phalanx_mm) return {-s_mm, rim_mm, cut_z_mm};  // the +y side, backwards
  if ((s_mm -= phalanx_mm) < back_arc_mm) {  // the back arc at x = -15, from +y over the top to -y
    const double a_rad = back_half_rad - s_mm / radius_mm;
    return {-phalanx_mm, radius_mm * std::sin(a_rad), radius_mm * std::cos(a_rad)};
  }
  if ((s_mm -= back_arc_mm) < phalanx_mm) return {s_mm - phalanx_mm, -rim_mm, cut_z_mm};  // the -y side
  // The tip's circle, from -90 to 0 degrees.
  const double a_rad = (s_mm - phalanx_mm) / rim_mm - std::numbers::pi / 2;
  return {rim_mm * std::cos(a_rad), rim_mm * std::sin(a_rad), cut_z_mm};
}

/// Each electrode's [start, end] arc length. Evenly spaced, except that an electrode which would
/// straddle a corner of the border is slid along it (by the least distance) to end at that corner:
/// a corner is a vertex of the faces, so a straddling electrode would be two curves, not one.
std::vector<std::array<double, 2>> electrode_spans_mm() {
  std::vector<std::array<double, 2>> spans;
  for (int i = 0; i < electrode_count; ++i) {
    double start_mm = i * border_mm / electrode_count - electrode_mm / 2;
    for (double corner_mm : corners_mm)
      if (start_mm < corner_mm && corner_mm < start_mm + electrode_mm)
        start_mm = (corner_mm - start_mm < electrode_mm / 2) ? corner_mm : corner_mm - electrode_mm;
    spans.push_back({start_mm, start_mm + electrode_mm});
  }
  return spans;
}

double distance_mm(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

/// A curve's length and its midpoint by arc length (sampled: exact enough for lines and arcs).
std::pair<double, Point> length_and_midpoint_mm(int curve) {
  std::vector<double> low, high;
  gmsh::model::getParametrizationBounds(1, curve, low, high);
  constexpr int samples = 2000;
  std::vector<double> params(samples + 1), xyz;
  for (int k = 0; k <= samples; ++k) params[k] = low[0] + (high[0] - low[0]) * k / samples;
  gmsh::model::getValue(1, curve, params, xyz);
  std::vector<double> cumulative_mm(samples + 1, 0);
  for (std::size_t k = 1; k <= static_cast<std::size_t>(samples); ++k)
    cumulative_mm[k] = cumulative_mm[k - 1] + distance_mm({xyz[3 * k - 3], xyz[3 * k - 2], xyz[3 * k - 1]},
                                                          {xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]});
  const double half_mm = cumulative_mm.back() / 2;
  const std::size_t k = std::lower_bound(cumulative_mm.begin(), cumulative_mm.end(), half_mm) - cumulative_mm.begin();
  const double t = (half_mm - cumulative_mm[k - 1]) / (cumulative_mm[k] - cumulative_mm[k - 1]);
  Point midpoint_mm;
  for (int d = 0; d < 3; ++d) midpoint_mm[d] = (1 - t) * xyz[3 * k - 3 + d] + t * xyz[3 * k + d];
  double length_mm = 0;
  occ::getMass(1, curve, length_mm);
  return {length_mm, midpoint_mm};
}

/// Builds the skin, splits its border at the electrodes' ends, and writes it to step_path.
void write_skin(const std::string& step_path) {
  // The half capsule. OCC puts a cylinder's seam at +z for an axis along x, and a sphere's poles at
  // +-z with its seam at +x: both turned about x so that no seam or pole lies on the skin.
  const int cylinder = occ::addCylinder(-phalanx_mm, 0, 0, phalanx_mm, 0, 0, radius_mm);
  occ::rotate({{3, cylinder}}, 0, 0, 0, 1, 0, 0, std::numbers::pi);  // seam to -z
  const int sphere = occ::addSphere(0, 0, 0, radius_mm);
  occ::rotate({{3, sphere}}, 0, 0, 0, 1, 0, 0, std::numbers::pi / 2);  // poles to +-y, seam to z = 0
  gmsh::vectorpair solid, above;
  std::vector<gmsh::vectorpair> map;
  occ::fuse({{3, cylinder}}, {{3, sphere}}, solid, map);
  const int box = occ::addBox(-phalanx_mm, -10, cut_z_mm, 25, 20, 7);  // x in [-15, 10], y in [-10, 10], z in [3, 10]
  occ::intersect(solid, {{3, box}}, above, map);
  occ::synchronize();

  // Keep the curved faces; drop the volume and the flat faces (at z = 3 and x = -15).
  gmsh::vectorpair faces, skin, flat;
  gmsh::model::getBoundary(above, faces, /*combined=*/true, /*oriented=*/false);
  for (const auto& face : faces) {
    std::string type;
    gmsh::model::getType(2, face.second, type);
    (type == "Plane" ? flat : skin).push_back(face);
  }
  occ::remove(above);
  occ::remove(flat, /*recursive=*/true);  // their own curves and points go; the skin's stay

  // Split the border at the electrodes' ends: points on its curves, fragmented with the faces.
  gmsh::vectorpair ends, fragments;
  for (const auto& span : electrode_spans_mm())
    for (double s_mm : span) {
      const Point p = border_point_mm(s_mm);
      ends.push_back({0, occ::addPoint(p[0], p[1], p[2])});
    }
  occ::fragment(skin, ends, fragments, map);
  occ::synchronize();
  gmsh::write(step_path);
}

/// Re-opens step_path and checks its area, border length and electrodes; prints what it measured.
bool check_skin(const std::string& step_path) {
  gmsh::clear();
  // Gmsh writes each face of a STEP file as its own shell, so the arc where the cylinder meets the
  // sphere is read back twice (once per face) and would count as border: sewing on import joins it.
  gmsh::option::setNumber("Geometry.OCCSewFaces", 1);
  gmsh::open(step_path);
  bool ok = true;
  auto report = [&ok](const char* what, double got, double want, double tolerance) {
    const bool pass = std::abs(got - want) <= tolerance;
    ok = ok && pass;
    std::printf("%-26s %10.4f  (expected %.4f +- %.4f)  %s\n", what, got, want, tolerance, pass ? "ok" : "FAIL");
  };

  gmsh::vectorpair surfaces, border;
  gmsh::model::getEntities(surfaces, 2);
  double area_mm2 = 0;
  for (const auto& surface : surfaces) {
    double a_mm2 = 0;
    occ::getMass(2, surface.second, a_mm2);
    area_mm2 += a_mm2;
  }
  const double want_area_mm2 = radius_mm * 2 * back_half_rad * phalanx_mm +            // the cylinder's strip
                               std::numbers::pi * radius_mm * (radius_mm - cut_z_mm);  // half the sphere's zone
  std::printf("%zu surfaces\n", surfaces.size());
  report("area (mm^2)", area_mm2, want_area_mm2, 1e-3 * want_area_mm2);

  // The border: the curves bounding exactly one surface.
  gmsh::model::getBoundary(surfaces, border, /*combined=*/true, /*oriented=*/false);
  double border_length_mm = 0;
  std::vector<std::pair<double, Point>> curves;
  std::vector<int> tags;
  for (const auto& curve : border) {
    tags.push_back(std::abs(curve.second));
    curves.push_back(length_and_midpoint_mm(tags.back()));
    border_length_mm += curves.back().first;
  }
  std::printf("%zu border curves\n", border.size());
  report("border length (mm)", border_length_mm, border_mm, 1e-3 * border_mm);

  // Each electrode is one border curve 3 mm long, with its midpoint where border_point_mm puts it.
  const auto electrodes_found = std::count_if(curves.begin(), curves.end(),
                                              [](const auto& c) { return std::abs(c.first - electrode_mm) <= 0.01; });
  report("curves 3.00 +- 0.01 mm", static_cast<double>(electrodes_found), electrode_count, 0);
  const auto spans = electrode_spans_mm();
  for (int i = 0; i < electrode_count; ++i) {
    const Point want = border_point_mm((spans[i][0] + spans[i][1]) / 2);
    const auto nearest = std::min_element(curves.begin(), curves.end(), [&want](const auto& a, const auto& b) {
      return distance_mm(a.second, want) < distance_mm(b.second, want);
    });
    const double off_mm = distance_mm(nearest->second, want);
    const bool pass = off_mm < 1e-3 && std::abs(nearest->first - electrode_mm) <= 0.01;
    ok = ok && pass;
    std::printf("electrode %2d: curve %2d, midpoint %8.4f %8.4f %8.4f (%.1e mm off), length %.4f mm  %s\n", i,
                tags[nearest - curves.begin()], nearest->second[0], nearest->second[1], nearest->second[2], off_mm,
                nearest->first, pass ? "ok" : "FAIL");
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const bool check_only = argc > 1 && std::string(argv[1]) == "--check";
  if (check_only && argc != 3) {
    std::fprintf(stderr, "usage: %s [OUT.step] | --check FILE.step\n", argv[0]);
    return 2;
  }
  const std::string path = check_only ? argv[2] : argc > 1 ? argv[1] : "examples/sensors/fingertip.step";
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Verbosity", 2);  // errors and warnings
  bool ok = false;
  try {
    if (!check_only) {
      write_skin(path);
      std::printf("wrote %s; border %.4f mm, electrodes (midpoint x y z in mm, arc length in mm):\n", path.c_str(),
                  border_mm);
      const auto spans = electrode_spans_mm();
      for (int i = 0; i < electrode_count; ++i) {
        const Point p = border_point_mm((spans[i][0] + spans[i][1]) / 2);
        std::printf("  %2d  {\"at_mm\": [%.4f, %.4f, %.4f]}  length %.4f  (arc %.4f to %.4f)\n", i, p[0], p[1], p[2],
                    spans[i][1] - spans[i][0], spans[i][0], spans[i][1]);
      }
    }
    ok = check_skin(path);
  } catch (const std::string& error) {  // Gmsh's API throws its last error as a string
    std::fprintf(stderr, "gmsh: %s\n", error.c_str());
  }
  gmsh::finalize();
  std::printf("%s\n", ok ? "check passed" : "check FAILED");
  return ok ? 0 : 1;
}
