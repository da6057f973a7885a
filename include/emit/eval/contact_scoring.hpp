#pragma once
/// \file contact_scoring.hpp
/// Contacts scored against the presses that made them, as tests/tools/score_contacts.py scores a
/// contacts file: a single press by its strongest contact (position, force, pressure, the force's
/// reported 1σ, a contact more than the one press), several presses by whether each has a contact
/// of its own within a distance.
#include <vector>

#include "emit/eval/error_stats.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

/// The contacts of each frame of a run, as a reconstructor reported them (strongest first).
using ContactSequence = std::vector<std::vector<Contact>>;

/// Frames of one press each.
struct SinglePressScore {
  int frames = 0;  ///< single-press frames scored
  /// The strongest contact's distance to the press [mm]; `missed`: frames without a contact.
  ErrorStats position_mm;
  double force_error = 0;  ///< mean |F̂ − F| / F over the frames with a contact (a fraction)
  double force_bias = 0;   ///< mean (F̂ − F) / F, the same frames: + when forces come out high
  /// Mean |P̂ − P| [N/mm²], P the press's mean pressure F/(πr²) (press.hpp), P̂ the contact's.
  double pressure_error_N_per_mm2 = 0;
  /// Fractions of the frames with a contact whose |F̂ − F| is at most 1 and 2 of the contact's
  /// reported force_std_N.
  double within_1_sigma = 0, within_2_sigma = 0;
  int extra_contacts = 0;  ///< frames with more than one contact: false contacts
};

/// Scores the frames of exactly one press; the others are skipped. \throw InvalidInput when
/// `contacts` and `presses` differ in length.
SinglePressScore score_single_presses(const ContactSequence& contacts, const PressSequence& presses);

/// Whether every press has a contact within `match_mm` of its centre, each contact matched at
/// most once: the presses in order, each takes the nearest contact not yet taken (as
/// score_contacts.py does; greedy, not the best assignment).
bool every_press_matched(const std::vector<Contact>& contacts, const std::vector<Press>& presses, double match_mm);

/// The fraction of frames where every_press_matched; 0 without frames. \throw InvalidInput when
/// `contacts` and `presses` differ in length.
double fraction_every_press_matched(const ContactSequence& contacts, const PressSequence& presses, double match_mm);

/// Whether a frame has a contact that is not a press: one left over when each press has taken
/// its nearest contact still left, and farther than `distance_mm` from every press (any contact,
/// in a frame without presses). A press's own contact placed far off is a position error, not a
/// false contact: on the 120 mm sheet the paper method's image of a central press is above half
/// its maximum nearly everywhere, one contact the size of the sheet, its centroid ~10 mm off.
bool has_false_contact(const std::vector<Contact>& contacts, const std::vector<Press>& presses, double distance_mm);

}  // namespace emit
