#include "emit/io/contacts_jsonl.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>

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
  return contact;
}

}  // namespace

void write_contacts_line(std::ostream& out, long frame, const std::vector<Contact>& contacts, double fit_misfit_mV) {
  check_finite(frame, contacts);
  if (!std::isfinite(fit_misfit_mV))
    throw InvalidInput("contacts of frame " + std::to_string(frame) + ": the fit's misfit is not finite");
  char head[64];
  std::snprintf(head, sizeof head, "{\"frame\": %ld, \"contacts\": [", frame);
  out << head;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    if (k > 0) out << ", ";
    write_contact(out, contacts[k]);
  }
  out << ']';
  if (fit_misfit_mV >= 0) {
    std::snprintf(head, sizeof head, ", \"fit_misfit_mV\": %.4g", fit_misfit_mV);
    out << head;
  }
  out << "}\n";
}

std::vector<Contact> parse_contacts_line(const std::string& line, long* frame) {
  const nlohmann::json document = parse_json(line);
  if (!document.is_object()) throw InvalidInput("contacts line: not a JSON object");
  const long number = frame_of(document);
  const nlohmann::json& list = member(document, "contacts", "contacts line");
  if (!list.is_array()) throw InvalidInput("contacts line: \"contacts\" is not an array");
  std::vector<Contact> contacts;
  contacts.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) contacts.push_back(contact_of(list[k], k));
  if (frame != nullptr) *frame = number;
  return contacts;
}

}  // namespace emit
