// A downstream program: the digital twin presses the built-in sensor at (X, Y) mm, and emit
// reconstructs the frame by contact fitting. Prints the contact; exits 0 when exactly one contact
// is found within 0.5 mm of the press (README: fit's p95 on this sheet is 0.13 mm), 1 when not,
// 2 on emit's errors. Usage: reconstruct_press X Y
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include <emit/frame/reconstructor.hpp>
#include <emit/pipeline/pipeline.hpp>
#include <emit/sensor/sensor_json.hpp>
#include <emit/twin/twin.hpp>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: reconstruct_press X Y\n");
    return 2;
  }
  const double x_mm = std::atof(argv[1]), y_mm = std::atof(argv[2]);
  try {
    const emit::Sensor sensor = emit::default_sensor();
    emit::Twin twin(sensor, {.mesh_seed = 3});  // the twin's own mesh, not the reconstruction's
    std::vector<emit::Frame> untouched;
    for (int i = 0; i < 10; ++i) untouched.push_back(twin.frame({}));

    emit::Pipeline pipeline(sensor, {.method = emit::Method::fit});
    emit::Reconstructor reconstructor = pipeline.reconstructor();
    reconstructor.set_reference(emit::average_reference(untouched));
    const std::vector<emit::Contact>& contacts =
        reconstructor.process(twin.frame({{.x_mm = x_mm, .y_mm = y_mm, .radius_mm = 5, .force_N = 10}}));

    for (const emit::Contact& c : contacts)
      std::printf("contact at (%.2f, %.2f) mm, %.2f N\n", c.x_mm, c.y_mm, c.force_N);
    const bool found = contacts.size() == 1 && std::hypot(contacts[0].x_mm - x_mm, contacts[0].y_mm - y_mm) < 0.5;
    return found ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reconstruct_press: %s\n", e.what());
    return 2;
  }
}
