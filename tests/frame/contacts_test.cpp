// Contacts from a selection of elements: connected components over shared edges, their area,
// force, pressures and centroid, the size filter, input checks, no allocation per frame, and the
// JSON Lines format.
#include "emit/frame/contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/core/errors.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

using test::machine_epsilon;

/// A 40 × 30 mm sheet of 1 mm square cells (two triangles each): element size h = 1 mm.
constexpr double h = 1.0;
Mesh sheet() { return test::strip_mesh(40.0, 30.0, 40, 30); }

/// The index of triangle k (0 or 1) of cell (i, j) of a strip_mesh with nx cells a row.
int cell_triangle(int i, int j, int k, int nx) { return 2 * (j * nx + i) + k; }

/// find()'s inputs: nothing selected, zero pressure, uniform weight.
struct Frame {
  std::vector<std::uint8_t> selected;
  Vector pressure, weight;
  explicit Frame(const Mesh& mesh)
      : selected(static_cast<std::size_t>(mesh.triangle_count()), 0),
        pressure(Vector::Zero(mesh.triangle_count())),
        weight(Vector::Ones(mesh.triangle_count())) {}
  void select(Index t, double p) {
    selected[static_cast<std::size_t>(t)] = 1;
    pressure[t] = p;
  }
};

/// Selects the elements whose centroid lies inside the disc, at uniform pressure.
void press_disc(const Mesh& mesh, Frame& frame, const Vector2& centre, double radius, double p) {
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    if ((mesh.triangle_centroid_mm(t).head<2>() - centre).norm() < radius) frame.select(t, p);
}

/// Σ A_k and Σ A_k c_k / Σ A_k over the selected elements, summed here independently of find().
struct Expected {
  double area = 0;
  Vector2 centroid = Vector2::Zero();
  int count = 0;
};
Expected selected_sums(const Mesh& mesh, const Frame& frame) {
  Expected e;
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    if (frame.selected[static_cast<std::size_t>(t)]) {
      e.area += mesh.triangle_area_mm2(t);
      e.centroid += mesh.triangle_area_mm2(t) * mesh.triangle_centroid_mm(t).head<2>();
      ++e.count;
    }
  e.centroid /= e.area;
  return e;
}

/// Sums of n positive terms in different orders (find()'s fill order vs. the test's index order)
/// agree to n ulps relative.
double summation_tolerance(int n) { return n * machine_epsilon; }

TEST(Contacts, OneDiscIsOneContactWithItsAreaAndCentre) {
  const Mesh mesh = sheet();
  Frame frame(mesh);
  const Vector2 centre(12.3, 17.6);  // off the grid's nodes and cell centres
  press_disc(mesh, frame, centre, 5.0, 0.02);
  const Expected expected = selected_sums(mesh, frame);
  ContactFinder finder(mesh);
  const auto& contacts = finder.find(frame.selected, frame.pressure, frame.weight);
  ASSERT_EQ(contacts.size(), 1u);
  const Contact& c = contacts[0];
  EXPECT_EQ(c.element_count, expected.count);
  EXPECT_NEAR(c.area_mm2, expected.area, summation_tolerance(expected.count) * expected.area);
  // The area-weighted centroid of exactly these elements (uniform weight): round-off only.
  EXPECT_NEAR(c.x_mm, expected.centroid.x(), summation_tolerance(expected.count) * 40.0);
  EXPECT_NEAR(c.y_mm, expected.centroid.y(), summation_tolerance(expected.count) * 30.0);
  // The elements approximate the disc: the outline is a staircase within one element of the
  // circle, and its excesses and shortfalls mostly cancel around the circle, so the centroid
  // lands well within h/2 of the centre (0.12 h here); a centroid one element off, or a swapped
  // axis, fails.
  EXPECT_LT((Vector2(c.x_mm, c.y_mm) - centre).norm(), 0.5 * h);
}

TEST(Contacts, TwoDiscsAreTwoContactsLargestForceFirst) {
  const Mesh mesh = sheet();
  Frame frame(mesh);
  // The larger disc presses lighter: sorting must follow force, not area.
  const double light = 0.01, heavy = 0.05;
  press_disc(mesh, frame, {10.0, 10.0}, 6.0, light);
  press_disc(mesh, frame, {30.0, 20.0}, 4.0, heavy);
  ContactFinder finder(mesh);
  const auto& contacts = finder.find(frame.selected, frame.pressure, frame.weight);
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_GT(contacts[0].force_N, contacts[1].force_N);
  EXPECT_LT(contacts[0].area_mm2, contacts[1].area_mm2);
  EXPECT_NEAR(contacts[0].x_mm, 30.0, 0.5 * h);  // the heavy disc (centroid bound as above)
  EXPECT_NEAR(contacts[1].x_mm, 10.0, 0.5 * h);
  const double pressures[] = {heavy, light};
  for (int k = 0; k < 2; ++k) {
    const Contact& c = contacts[k];
    const double tolerance = summation_tolerance(c.element_count);
    // Σ P A_k = P Σ A_k for uniform P, up to the rounding of each term.
    EXPECT_NEAR(c.force_N, pressures[k] * c.area_mm2, tolerance * c.force_N);
    EXPECT_NEAR(c.pressure_N_per_mm2, pressures[k], tolerance * pressures[k]);
    EXPECT_EQ(c.peak_pressure_N_per_mm2, pressures[k]);  // a max, no arithmetic
  }
}

TEST(Contacts, MeanAndPeakPressureOfANonUniformContact) {
  const Mesh mesh = sheet();
  Frame frame(mesh);
  const int nx = 40;
  // Two cells side by side (4 triangles of 0.5 mm²): pressures 1, 2, 3, 4.
  for (int k = 0; k < 4; ++k) frame.select(cell_triangle(5 + k / 2, 5, k % 2, nx), 1.0 + k);
  ContactFinder finder(mesh);
  const auto& contacts = finder.find(frame.selected, frame.pressure, frame.weight);
  ASSERT_EQ(contacts.size(), 1u);
  // Small exact sums of halves: no rounding at all.
  EXPECT_EQ(contacts[0].force_N, 0.5 * (1 + 2 + 3 + 4));
  EXPECT_EQ(contacts[0].pressure_N_per_mm2, 2.5);
  EXPECT_EQ(contacts[0].peak_pressure_N_per_mm2, 4.0);
}

TEST(Contacts, RegionsTouchingAtAVertexAreSeparate) {
  const Mesh mesh = sheet();
  const int nx = 40;
  ContactFinder finder(mesh);
  // Cells (5, 5) and (6, 6) share only the node (6, 6); so do cells (12, 6) and (11, 5), the other
  // diagonal direction (the two meet the shared node with different triangle layouts).
  Frame frame(mesh);
  for (int k = 0; k < 2; ++k) {
    frame.select(cell_triangle(5, 5, k, nx), 1.0);
    frame.select(cell_triangle(6, 6, k, nx), 1.0);
    frame.select(cell_triangle(12, 6, k, nx), 1.0);
    frame.select(cell_triangle(11, 5, k, nx), 1.0);
  }
  EXPECT_EQ(finder.find(frame.selected, frame.pressure, frame.weight).size(), 4u);
  for (int k = 0; k < 2; ++k) {  // drop the second pair again
    frame.selected[cell_triangle(12, 6, k, nx)] = 0;
    frame.selected[cell_triangle(11, 5, k, nx)] = 0;
  }
  // Cell (6, 5) shares an edge with each: then they are one contact of three cells.
  for (int k = 0; k < 2; ++k) frame.select(cell_triangle(6, 5, k, nx), 1.0);
  const auto& joined = finder.find(frame.selected, frame.pressure, frame.weight);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].element_count, 6);
  EXPECT_EQ(joined[0].area_mm2, 3.0);  // six halves of 1 mm²: exact
}

TEST(Contacts, MinAreaDropsSpecks) {
  const Mesh mesh = sheet();
  Frame frame(mesh);
  press_disc(mesh, frame, {20.0, 15.0}, 4.0, 0.02);
  const Index speck = cell_triangle(35, 25, 0, 40);  // one triangle of exactly 0.5 mm², far away
  frame.select(speck, 0.1);
  ContactFinder finder(mesh);
  EXPECT_EQ(finder.find(frame.selected, frame.pressure, frame.weight).size(), 2u);
  EXPECT_EQ(finder.find(frame.selected, frame.pressure, frame.weight, 0.5).size(), 2u);  // not smaller: kept
  const auto& kept = finder.find(frame.selected, frame.pressure, frame.weight, 0.6);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_GT(kept[0].area_mm2, 40.0);  // the disc (≈ 50 mm²), although the speck has more force per area
  EXPECT_TRUE(finder.find(frame.selected, frame.pressure, frame.weight, 1e3).empty());
}

TEST(Contacts, CentroidFollowsTheWeights) {
  const Mesh mesh = sheet();
  Frame frame(mesh);
  press_disc(mesh, frame, {20.0, 15.0}, 4.0, 0.02);
  ContactFinder finder(mesh);
  // All weight on one element: the centroid is that element's.
  const Index t = cell_triangle(21, 15, 1, 40);
  ASSERT_TRUE(frame.selected[static_cast<std::size_t>(t)]);
  frame.weight.setZero();
  frame.weight[t] = 3.0;
  const Contact one = finder.find(frame.selected, frame.pressure, frame.weight)[0];
  EXPECT_NEAR(one.x_mm, mesh.triangle_centroid_mm(t).x(), 1e-12);  // w A c / (w A): round-off
  EXPECT_NEAR(one.y_mm, mesh.triangle_centroid_mm(t).y(), 1e-12);
  // All weights 0: the area-weighted centroid.
  frame.weight.setZero();
  const Contact none = finder.find(frame.selected, frame.pressure, frame.weight)[0];
  const Expected expected = selected_sums(mesh, frame);
  EXPECT_NEAR(none.x_mm, expected.centroid.x(), summation_tolerance(expected.count) * 40.0);
  EXPECT_NEAR(none.y_mm, expected.centroid.y(), summation_tolerance(expected.count) * 30.0);
}

TEST(Contacts, WrongInputSizesThrow) {
  const Mesh mesh = sheet();
  ContactFinder finder(mesh);
  const Frame frame(mesh);
  std::vector<std::uint8_t> short_selection(frame.selected.size() - 1, 0);
  const Vector long_vector = Vector::Zero(mesh.triangle_count() + 1);
  EXPECT_THROW(finder.find(short_selection, frame.pressure, frame.weight), InvalidInput);
  EXPECT_THROW(finder.find(frame.selected, long_vector, frame.weight), InvalidInput);
  EXPECT_THROW(finder.find(frame.selected, frame.pressure, Vector()), InvalidInput);
  try {
    finder.find(frame.selected, frame.pressure, long_vector);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("weight"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(std::to_string(mesh.triangle_count())), std::string::npos) << e.what();
  }
}

/// Reference components by union-find over a map of edges, sharing no code with ContactFinder.
std::vector<int> reference_component_sizes(const Mesh& mesh, const std::vector<std::uint8_t>& selected) {
  std::vector<int> parent(static_cast<std::size_t>(mesh.triangle_count()));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  std::map<std::array<int, 2>, int> first_user;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    if (!selected[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      const auto [it, fresh] = first_user.insert({{std::min(a, b), std::max(a, b)}, t});
      if (!fresh) parent[root(t)] = root(it->second);
    }
  }
  std::map<int, int> sizes;
  for (int t = 0; t < mesh.triangle_count(); ++t)
    if (selected[t]) ++sizes[root(t)];
  std::vector<int> result;
  result.reserve(sizes.size());
  for (const auto& [r, n] : sizes) result.push_back(n);
  std::sort(result.begin(), result.end());
  return result;
}

TEST(Contacts, RandomSelectionsMatchAReferenceLabelling) {
  const Mesh mesh = sheet();
  ContactFinder finder(mesh);
  std::mt19937 random(7);
  // Densities around the percolation range give many components of all sizes.
  for (double density : {0.2, 0.45, 0.6, 0.9}) {
    Frame frame(mesh);
    std::bernoulli_distribution coin(density);
    std::uniform_real_distribution<double> pressure(0.001, 0.1);
    for (Index t = 0; t < mesh.triangle_count(); ++t)
      if (coin(random)) frame.select(t, pressure(random));
    const auto& contacts = finder.find(frame.selected, frame.pressure, frame.weight);
    std::vector<int> sizes;
    sizes.reserve(contacts.size());
    for (const Contact& c : contacts) sizes.push_back(c.element_count);
    std::sort(sizes.begin(), sizes.end());
    EXPECT_EQ(sizes, reference_component_sizes(mesh, frame.selected)) << "density " << density;
    EXPECT_TRUE(std::is_sorted(contacts.begin(), contacts.end(),
                               [](const Contact& a, const Contact& b) { return a.force_N > b.force_N; }));
  }
}

TEST(Contacts, FindAllocatesNothing) {
  // 50 × 50 cells of 1.2 mm: 5000 triangles, the size of the paper's reconstruction mesh.
  const Mesh mesh = test::strip_mesh(60.0, 60.0, 50, 50);
  ContactFinder finder(mesh);
  Frame frame(mesh);
  press_disc(mesh, frame, {15.0, 15.0}, 6.0, 0.02);
  press_disc(mesh, frame, {45.0, 20.0}, 4.0, 0.05);
  press_disc(mesh, frame, {30.0, 45.0}, 8.0, 0.01);
  frame.select(cell_triangle(2, 48, 0, 50), 0.03);                 // a speck, dropped below
  finder.find(frame.selected, frame.pressure, frame.weight, 1.0);  // warm-up
  {
    const test::AllocationCounter counter;
    const auto& contacts = finder.find(frame.selected, frame.pressure, frame.weight, 1.0);
    EXPECT_EQ(counter.count(), 0);
    EXPECT_EQ(contacts.size(), 3u);
  }
  // The worst cases the buffers were sized for, with no warm-up at their size: the most
  // components (the first triangle of every other cell, a checkerboard touching only at vertices)
  // and the deepest stack (everything selected).
  Frame checkerboard(mesh), everything(mesh);
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 50; ++i)
      if ((i + j) % 2 == 0) checkerboard.select(cell_triangle(i, j, 0, 50), 0.01);
  for (Index t = 0; t < mesh.triangle_count(); ++t) everything.select(t, 0.01);
  const test::AllocationCounter counter;
  const std::size_t isolated = finder.find(checkerboard.selected, checkerboard.pressure, checkerboard.weight).size();
  const std::size_t whole = finder.find(everything.selected, everything.pressure, everything.weight).size();
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(isolated, 1250u);
  EXPECT_EQ(whole, 1u);
}

TEST(Contacts, EmptyMeshAndEmptySelection) {
  const Mesh mesh = sheet();
  ContactFinder finder(mesh);
  const Frame frame(mesh);
  EXPECT_TRUE(finder.find(frame.selected, frame.pressure, frame.weight).empty());
  ContactFinder nothing{Mesh{}};
  EXPECT_EQ(nothing.element_count(), 0);
  EXPECT_TRUE(nothing.find({}, Vector(), Vector()).empty());
}

// ---- JSON Lines ----

std::vector<Contact> two_contacts() {
  Contact a, b;
  a.x_mm = 12.3456789, a.y_mm = 0.000123456789, a.area_mm2 = 1234.56789;
  a.pressure_N_per_mm2 = 0.0123456789, a.peak_pressure_N_per_mm2 = 0.1, a.force_N = 15.2345678;
  b.x_mm = 59.999999, b.y_mm = 3e-7, b.area_mm2 = 0.5;
  b.pressure_N_per_mm2 = 2.5e-3, b.peak_pressure_N_per_mm2 = 987654.321, b.force_N = -1.0;
  return {a, b};
}

/// %.6g keeps 6 significant digits: a relative rounding error of at most 5e-6.
void expect_near_printed(double actual, double expected, const char* key) {
  EXPECT_NEAR(actual, expected, 1e-5 * std::abs(expected)) << key;
}

TEST(ContactsJsonl, RoundTrip) {
  const std::vector<Contact> written = two_contacts();
  std::ostringstream out;
  write_contacts_line(out, 42, written);
  const std::string line = out.str();
  ASSERT_EQ(line.back(), '\n');
  EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1);  // one line per frame
  long frame = -1;
  const std::vector<Contact> read = parse_contacts_line(line, &frame);
  EXPECT_EQ(frame, 42);
  ASSERT_EQ(read.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    expect_near_printed(read[k].x_mm, written[k].x_mm, "x_mm");
    expect_near_printed(read[k].y_mm, written[k].y_mm, "y_mm");
    expect_near_printed(read[k].area_mm2, written[k].area_mm2, "area_mm2");
    expect_near_printed(read[k].pressure_N_per_mm2, written[k].pressure_N_per_mm2, "pressure_N_per_mm2");
    expect_near_printed(read[k].peak_pressure_N_per_mm2, written[k].peak_pressure_N_per_mm2, "peak");
    expect_near_printed(read[k].force_N, written[k].force_N, "force_N");
  }
}

TEST(ContactsJsonl, KeysInTheDocumentedOrder) {
  std::ostringstream out;
  write_contacts_line(out, 7, {two_contacts()[0]});
  const std::string line = out.str();
  std::size_t previous = 0;
  for (const char* key : {"\"frame\"", "\"contacts\"", "\"x_mm\"", "\"y_mm\"", "\"area_mm2\"", "\"pressure_N_per_mm2\"",
                          "\"peak_pressure_N_per_mm2\"", "\"force_N\""}) {
    const std::size_t at = line.find(key);
    ASSERT_NE(at, std::string::npos) << key << " in " << line;
    EXPECT_GE(at, previous) << key << " in " << line;
    previous = at;
  }
}

TEST(ContactsJsonl, UncertaintiesAndTheFitsMisfitRoundTripWhenThere) {
  std::vector<Contact> written = two_contacts();
  written[0].x_std_mm = 0.031, written[0].y_std_mm = 0.027, written[0].pressure_std_N_per_mm2 = 0.0042;
  std::ostringstream out;
  write_contacts_line(out, 5, written, 1.23);
  const std::string line = out.str();
  EXPECT_NE(line.find("\"fit_misfit_mV\": 1.23"), std::string::npos) << line;
  // Only the contact that has them carries the uncertainty keys.
  EXPECT_EQ(line.find("x_std_mm"), line.rfind("x_std_mm")) << line;
  const std::vector<Contact> read = parse_contacts_line(line);
  ASSERT_EQ(read.size(), 2u);
  expect_near_printed(read[0].x_std_mm, 0.031, "x_std_mm");
  expect_near_printed(read[0].y_std_mm, 0.027, "y_std_mm");
  expect_near_printed(read[0].pressure_std_N_per_mm2, 0.0042, "pressure_std");
  EXPECT_EQ(read[1].x_std_mm, 0.0);
  std::ostringstream without;
  write_contacts_line(without, 5, two_contacts());
  EXPECT_EQ(without.str().find("std"), std::string::npos) << "the linear methods estimate no uncertainty";
  EXPECT_EQ(without.str().find("fit_misfit_mV"), std::string::npos);
}

TEST(ContactsJsonl, EmptyContactsList) {
  std::ostringstream out;
  write_contacts_line(out, 3, {});
  EXPECT_NE(out.str().find("\"contacts\": []"), std::string::npos) << out.str();
  long frame = -1;
  EXPECT_TRUE(parse_contacts_line(out.str(), &frame).empty());
  EXPECT_EQ(frame, 3);
}

/// The message of the InvalidInput that parsing `line` throws, or "" when it does not throw.
std::string parse_error(const std::string& line) {
  try {
    parse_contacts_line(line);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(ContactsJsonl, BadLinesThrowNamingTheProblem) {
  const std::string contact_without_force =
      R"({"x_mm": 1, "y_mm": 2, "area_mm2": 3, "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5})";
  EXPECT_NE(parse_error(R"({"frame": 1, "contacts": [)" + contact_without_force + "]}").find("force_N"),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"contacts": []})").find("frame"), std::string::npos);
  EXPECT_NE(parse_error(R"({"frame": 1})").find("contacts"), std::string::npos);
  EXPECT_NE(parse_error(R"({"frame": 1.5, "contacts": []})").find("frame"), std::string::npos);
  const std::string text_x = R"({"frame": 1, "contacts": [{"x_mm": "one", "y_mm": 2, "area_mm2": 3,
      "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5, "force_N": 6}]})";
  EXPECT_NE(parse_error(text_x).find("x_mm"), std::string::npos);
  EXPECT_NE(parse_error("not json").find("JSON"), std::string::npos);
  EXPECT_NE(parse_error("[]").find("object"), std::string::npos);
}

TEST(ContactsJsonl, NonFiniteValuesAreRefusedBeforeWriting) {
  std::vector<Contact> contacts = two_contacts();
  contacts[1].force_N = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream out;
  EXPECT_THROW(write_contacts_line(out, 1, contacts), InvalidInput);
  EXPECT_TRUE(out.str().empty());  // no half line left in the stream
}

}  // namespace
}  // namespace emit
