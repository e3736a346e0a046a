// The JSON form of a replay's scene record (core/scene_record.h), as a
// replay file holds it in `scene.record` (docs/replay-format.md).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "core/result.h"
#include "core/scene_record.h"

namespace bx {

/// The record as JSON: lists left empty are left out; times, positions,
/// sizes, rates and quaternions rounded to 1e-6, field values to 1e-3. The
/// same record gives the same text.
nlohmann::json scene_record_to_json(const SceneRecord& r);

/// Reads what scene_record_to_json wrote (a missing list is empty); an error
/// names the field's path under `path` and what was wrong with it, e.g.
/// "scene.record.events[3].cell.kind: no such cell kind (the record has 7), got 9".
Result<SceneRecord> scene_record_from_json(const nlohmann::json& j, const std::string& path = "scene.record");

}  // namespace bx
