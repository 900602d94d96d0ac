/// @file record.hpp
/// @brief A record is an ordered JSON object; keys keep their input order so
/// fields a tool does not own pass through unchanged and in place.
#pragma once

#include <nlohmann/json.hpp>

namespace tk {

using Record = nlohmann::ordered_json;

}  // namespace tk
