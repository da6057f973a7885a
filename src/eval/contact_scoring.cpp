#include "emit/eval/contact_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

void check_lengths(const ContactSequence& contacts, const PressSequence& presses) {
  if (contacts.size() != presses.size())
    throw InvalidInput("scoring contacts: " + std::to_string(contacts.size()) + " frames of contacts for " +
                       std::to_string(presses.size()) + " frames of presses");
}

}  // namespace

SinglePressScore score_single_presses(const ContactSequence& contacts, const PressSequence& presses) {
  check_lengths(contacts, presses);
  SinglePressScore score;
  std::vector<double> errors_mm;
  int missed = 0, within_1 = 0, within_2 = 0;
  for (std::size_t f = 0; f < presses.size(); ++f) {
    if (presses[f].size() != 1) continue;
    ++score.frames;
    const Press& truth = presses[f][0];
    const std::vector<Contact>& found = contacts[f];
    if (found.empty()) {
      ++missed;
      continue;
    }
    const Contact& strongest = found.front();
    errors_mm.push_back(position_error_mm(strongest, truth));
    const double force_error_N = strongest.force_N - truth.force_N;
    score.force_error += std::abs(force_error_N) / truth.force_N;
    score.force_bias += force_error_N / truth.force_N;
    score.pressure_error_N_per_mm2 += std::abs(strongest.pressure_N_per_mm2 - truth.pressure_N_per_mm2());
    within_1 += std::abs(force_error_N) <= strongest.force_std_N;
    within_2 += std::abs(force_error_N) <= 2 * strongest.force_std_N;
    score.extra_contacts += found.size() > 1;
  }
  score.position_mm = summarize_errors(errors_mm, missed);
  if (const auto found = static_cast<double>(errors_mm.size()); found > 0) {
    score.force_error /= found, score.force_bias /= found, score.pressure_error_N_per_mm2 /= found;
    score.within_1_sigma = within_1 / found, score.within_2_sigma = within_2 / found;
  }
  return score;
}

bool every_press_matched(const std::vector<Contact>& contacts, const std::vector<Press>& presses, double match_mm) {
  std::vector<bool> taken(contacts.size(), false);
  for (const Press& p : presses) {
    std::size_t nearest = contacts.size();
    double nearest_mm = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < contacts.size(); ++i)
      if (const double d = position_error_mm(contacts[i], p); !taken[i] && d < nearest_mm) nearest = i, nearest_mm = d;
    if (nearest == contacts.size() || nearest_mm > match_mm) return false;
    taken[nearest] = true;
  }
  return true;
}

double fraction_every_press_matched(const ContactSequence& contacts, const PressSequence& presses, double match_mm) {
  check_lengths(contacts, presses);
  if (presses.empty()) return 0;
  int matched = 0;
  for (std::size_t f = 0; f < presses.size(); ++f) matched += every_press_matched(contacts[f], presses[f], match_mm);
  return matched / static_cast<double>(presses.size());
}

bool has_false_contact(const std::vector<Contact>& contacts, const std::vector<Press>& presses, double distance_mm) {
  const auto distance = [](const Contact& c, const Press& p) { return position_error_mm(c, p); };
  std::vector<Contact> left(contacts.begin(), contacts.end());
  for (const Press& p : presses) {
    if (left.empty()) break;
    left.erase(std::min_element(left.begin(), left.end(),
                                [&](const Contact& a, const Contact& b) { return distance(a, p) < distance(b, p); }));
  }
  return std::any_of(left.begin(), left.end(), [&](const Contact& c) {
    return std::all_of(presses.begin(), presses.end(), [&](const Press& p) { return distance(c, p) > distance_mm; });
  });
}

}  // namespace emit
