#include "genome/json_text.h"

#include "core/text.h"

namespace bx {

namespace {

// a copy of `v` with every string and key made UTF-8
template <class J>
J as_utf8(const J& v) {
  if (v.is_string()) return J(utf8_text(v.template get_ref<const typename J::string_t&>()));
  if (v.is_array()) {
    J out = J::array();
    for (const J& e : v) out.push_back(as_utf8(e));
    return out;
  }
  if (v.is_object()) {
    J out = J::object();
    for (auto it = v.begin(); it != v.end(); ++it) out[utf8_text(it.key())] = as_utf8(it.value());
    return out;
  }
  return v;
}

template <class J>
std::string utf8_dump(const J& v, int indent) {
  try {
    return v.dump(indent);
  } catch (const typename J::type_error&) {
    // dump's one refusal (type_error 316): a string that is not UTF-8; the
    // copy costs nothing unless one is
    return as_utf8(v).dump(indent);
  }
}

}  // namespace

std::string json_text(const nlohmann::json& v, int indent) { return utf8_dump(v, indent); }
std::string json_text(const nlohmann::ordered_json& v, int indent) { return utf8_dump(v, indent); }

}  // namespace bx
