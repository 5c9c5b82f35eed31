// What the params rows cannot say: conditions between keys of the configuration, checked once
// every section is read (parse_config), each naming the key at fault.
#pragma once

#include "config_reading.hpp"

#include "semimesh/pipeline/config.hpp"

#include <map>
#include <string>

namespace semimesh::pipeline::detail {

/// Throws ConfigError at the first condition broken, in section order. Makes geometry.source
/// absolute (relative to `base_directory`, the config file's folder).
void check_across_keys(Config& c, const std::map<std::string, Section*>& sections, const std::string& base_directory);

}  // namespace semimesh::pipeline::detail
