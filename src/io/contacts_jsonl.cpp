#include "emit/io/contacts_jsonl.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <utility>

#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// A contact's numbers in the line, in the documented order; the writer and the parser share it.
/// element_count is not part of the format (the parser leaves it 0).
enum class Group {
  always,
  uncertainty,        ///< written only when some 1σ is nonzero (contact fitting); may be absent
  surface,            ///< written only off the plane z = 0 (a curved sheet); absent: z = 0, normal +z
  shape,              ///< the outline's ellipse, written when it has one (frame/contacts.hpp); may be absent
  shape_uncertainty,  ///< its 1σ, written when estimated (the `shapes` method); may be absent
  tracked,            ///< written for a tracked contact (id ≥ 0, frame/contact_tracker.hpp); may be absent
};
struct Field {
  const char* key;
  double Contact::*value;
  Group group;
};
constexpr Field fields[] = {
    {"x_mm", &Contact::x_mm, Group::always},
    {"y_mm", &Contact::y_mm, Group::always},
    {"z_mm", &Contact::z_mm, Group::surface},
    {"nx", &Contact::nx, Group::surface},
    {"ny", &Contact::ny, Group::surface},
    {"nz", &Contact::nz, Group::surface},
    {"area_mm2", &Contact::area_mm2, Group::always},
    {"pressure_N_per_mm2", &Contact::pressure_N_per_mm2, Group::always},
    {"peak_pressure_N_per_mm2", &Contact::peak_pressure_N_per_mm2, Group::always},
    {"force_N", &Contact::force_N, Group::always},
    {"x_std_mm", &Contact::x_std_mm, Group::uncertainty},
    {"y_std_mm", &Contact::y_std_mm, Group::uncertainty},
    {"pressure_std_N_per_mm2", &Contact::pressure_std_N_per_mm2, Group::uncertainty},
    {"force_std_N", &Contact::force_std_N, Group::uncertainty},
    {"semi_major_mm", &Contact::semi_major_mm, Group::shape},
    {"semi_minor_mm", &Contact::semi_minor_mm, Group::shape},
    {"orientation_deg", &Contact::orientation_deg, Group::shape},
    {"area_std_mm2", &Contact::area_std_mm2, Group::shape_uncertainty},
    {"orientation_std_deg", &Contact::orientation_std_deg, Group::shape_uncertainty},
    {"vx_mm_per_s", &Contact::vx_mm_per_s, Group::tracked},
    {"vy_mm_per_s", &Contact::vy_mm_per_s, Group::tracked},
};

bool has_uncertainty(const Contact& c) { return c.x_std_mm > 0 || c.y_std_mm > 0 || c.pressure_std_N_per_mm2 > 0; }
bool off_the_plane(const Contact& c) { return c.z_mm != 0 || c.nx != 0 || c.ny != 0 || c.nz != 1; }

bool written(const Field& field, const Contact& c) {
  switch (field.group) {
    case Group::always: return true;
    case Group::uncertainty: return has_uncertainty(c);
    case Group::surface: return off_the_plane(c);
    case Group::shape: return c.semi_major_mm > 0;
    case Group::shape_uncertainty: return c.area_std_mm2 > 0 || c.orientation_std_deg > 0;
    case Group::tracked: return c.id >= 0;
  }
  return true;
}

/// JSON has no NaN or infinity; refuse before writing anything, so no half line is left behind.
void check_finite(long frame, const std::vector<Contact>& contacts) {
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    for (const Field& field : fields)
      if (!std::isfinite(contacts[k].*field.value))
        throw InvalidInput("contacts of frame " + std::to_string(frame) + ": contact " + std::to_string(k) + "'s " +
                           field.key + " is not finite");
    const Outline& outline = contacts[k].outline;
    for (int v = 0; v < outline.size; ++v)
      if (!outline.vertex_mm(v).allFinite())
        throw InvalidInput("contacts of frame " + std::to_string(frame) + ": contact " + std::to_string(k) +
                           "'s outline_mm vertex " + std::to_string(v) + " is not finite");
  }
}

/// The outline's vertices as [[x, y], …], each to 6 significant digits like the other numbers
/// (std::to_chars: %.6g's digits without the locale, and a few times faster for 64 vertices).
void write_outline(std::ostream& out, const Outline& outline) {
  char text[40];
  out << ", \"outline_mm\": [";
  for (int k = 0; k < outline.size; ++k) {
    char* end = text;
    if (k > 0) *end++ = ',', *end++ = ' ';
    *end++ = '[';
    const Vector2 p = outline.vertex_mm(k);
    end = std::to_chars(end, text + sizeof text, p.x(), std::chars_format::general, 6).ptr;
    *end++ = ',', *end++ = ' ';
    end = std::to_chars(end, text + sizeof text, p.y(), std::chars_format::general, 6).ptr;
    *end++ = ']';
    out.write(text, end - text);
  }
  out << ']';
}

/// snprintf's %g follows LC_NUMERIC; emit never calls setlocale, so the decimal point is '.'.
void write_contact(std::ostream& out, const Contact& contact) {
  char text[96];  // the longest key (23) + quotes and separators + a %.6g number (at most 13) fit
  out << '{';
  const char* separator = "";
  if (contact.id >= 0) {  // first: a reader keys touches by it
    std::snprintf(text, sizeof text, "\"id\": %lld, \"phase\": \"%s\"", static_cast<long long>(contact.id),
                  touch_phase_name(contact.phase));
    out << text;
    separator = ", ";
  }
  for (const Field& field : fields) {
    if (!written(field, contact)) continue;
    std::snprintf(text, sizeof text, "%s\"%s\": %.6g", separator, field.key, contact.*field.value);
    out << text;
    separator = ", ";
  }
  if (!contact.outline.empty()) write_outline(out, contact.outline);
  out << '}';
}

nlohmann::json parse_json(const std::string& line) {
  try {
    return nlohmann::json::parse(line);
  } catch (const nlohmann::json::parse_error& e) {
    throw InvalidInput(std::string("contacts line: not valid JSON (") + e.what() + ")");
  } catch (const nlohmann::json::out_of_range& e) {  // a number beyond a double's range: 1e999
    throw InvalidInput(std::string("contacts line: a number out of range (") + e.what() + ")");
  }
}

const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) throw InvalidInput(where + ": missing \"" + key + "\"");
  return *it;
}

long frame_of(const nlohmann::json& line) {
  const nlohmann::json& frame = member(line, "frame", "contacts line");
  if (!frame.is_number_integer()) throw InvalidInput("contacts line: \"frame\" is not an integer");
  return frame.get<long>();
}

/// Unknown keys are ignored, so a reader keeps working when the format gains a key.
Contact contact_of(const nlohmann::json& object, std::size_t k) {
  const std::string where = "contacts line: contact " + std::to_string(k);
  if (!object.is_object()) throw InvalidInput(where + " is not an object");
  Contact contact;
  for (const Field& field : fields) {
    if (field.group != Group::always && !object.contains(field.key)) continue;
    const nlohmann::json& value = member(object, field.key, where);
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      throw InvalidInput(where + ": \"" + field.key + "\" is not a finite number");
    contact.*field.value = value.get<double>();
  }
  if (const auto outline = object.find("outline_mm"); outline != object.end()) {
    if (!outline->is_array() || outline->size() < 3 || outline->size() > static_cast<std::size_t>(Outline::capacity))
      throw InvalidInput(where + ": \"outline_mm\" is not a list of 3 to " + std::to_string(Outline::capacity) +
                         " vertices");
    for (std::size_t v = 0; v < outline->size(); ++v) {
      const nlohmann::json& vertex = (*outline)[v];
      if (!vertex.is_array() || vertex.size() != 2 || !vertex[0].is_number() || !vertex[1].is_number() ||
          !std::isfinite(vertex[0].get<double>()) || !std::isfinite(vertex[1].get<double>()))
        throw InvalidInput(where + ": \"outline_mm\" vertex " + std::to_string(v) + " is not [x, y], finite numbers");
      contact.outline.push_back({vertex[0].get<double>(), vertex[1].get<double>()});
    }
  }
  if (const auto id = object.find("id"); id != object.end()) {
    if (!id->is_number_integer() || id->get<long long>() < 0)
      throw InvalidInput(where + ": \"id\" is not a non-negative integer");
    contact.id = id->get<std::int64_t>();
    contact.phase = TouchPhase::move;
  }
  if (const auto phase = object.find("phase"); phase != object.end()) {
    const auto* name = phase->get_ptr<const std::string*>();
    constexpr TouchPhase phases[] = {TouchPhase::down, TouchPhase::move, TouchPhase::up};
    const auto* known = std::find_if(std::begin(phases), std::end(phases),
                                     [&](TouchPhase p) { return name && *name == touch_phase_name(p); });
    if (known == std::end(phases)) throw InvalidInput(where + ": \"phase\" is not one of \"down\", \"move\", \"up\"");
    contact.phase = *known;
  }
  return contact;
}

}  // namespace

void write_contacts_line(std::ostream& out, long frame, const std::vector<Contact>& contacts, double fit_misfit_mV,
                         const FrameTimes& times, const std::vector<Contact>* ended) {
  check_finite(frame, contacts);
  if (ended) check_finite(frame, *ended);
  if (!std::isfinite(fit_misfit_mV))
    throw InvalidInput("contacts of frame " + std::to_string(frame) + ": the fit's misfit is not finite");
  char head[64];
  std::snprintf(head, sizeof head, "{\"frame\": %ld", frame);
  out << head;
  // Microseconds: %.6f of a Unix time in seconds; a board's clock to %.9g (µs over hours).
  if (std::isfinite(times.board_s)) {
    std::snprintf(head, sizeof head, ", \"board_time_s\": %.9g", times.board_s);
    out << head;
  }
  if (std::isfinite(times.host_unix_s)) {
    std::snprintf(head, sizeof head, ", \"host_time_s\": %.6f", times.host_unix_s);
    out << head;
  }
  const auto write_list = [&](const char* key, const std::vector<Contact>& list) {
    out << ", \"" << key << "\": [";
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (k > 0) out << ", ";
      write_contact(out, list[k]);
    }
    out << ']';
  };
  write_list("contacts", contacts);
  if (ended && !ended->empty()) write_list("ended", *ended);
  if (fit_misfit_mV >= 0) {
    std::snprintf(head, sizeof head, ", \"fit_misfit_mV\": %.4g", fit_misfit_mV);
    out << head;
  }
  out << "}\n";
}

ContactsLine parse_contacts_record(const std::string& line) {
  const nlohmann::json document = parse_json(line);
  if (!document.is_object()) throw InvalidInput("contacts line: not a JSON object");
  ContactsLine read;
  read.frame = frame_of(document);
  const auto list_of = [&](const char* key, std::vector<Contact>& into) {
    const nlohmann::json& list = member(document, key, "contacts line");
    if (!list.is_array()) throw InvalidInput(std::string("contacts line: \"") + key + "\" is not an array");
    into.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) into.push_back(contact_of(list[k], k));
  };
  list_of("contacts", read.contacts);
  if (document.contains("ended")) list_of("ended", read.ended);
  const auto number = [&](const char* key, double& into) {
    const auto it = document.find(key);
    if (it == document.end()) return;
    if (!it->is_number() || !std::isfinite(it->get<double>()))
      throw InvalidInput(std::string("contacts line: \"") + key + "\" is not a finite number");
    into = it->get<double>();
  };
  number("board_time_s", read.times.board_s);
  number("host_time_s", read.times.host_unix_s);
  number("fit_misfit_mV", read.fit_misfit_mV);
  return read;
}

std::vector<Contact> parse_contacts_line(const std::string& line, long* frame) {
  ContactsLine read = parse_contacts_record(line);
  if (frame != nullptr) *frame = read.frame;
  return std::move(read.contacts);
}

}  // namespace emit
