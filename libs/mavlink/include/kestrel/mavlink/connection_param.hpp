#pragma once
// The `connection` parameter as every node of a MAVLink link declares it (INTERFACES.md: one name,
// MAVSDK's URL forms), with the rule that refuses a URL that cannot be read when the graph is
// validated, at the value's file:line:col.
#include <kestrel/config_spec.hpp>
#include <string>

#include "kestrel/mavlink/connection_url.hpp"

namespace kestrel::mavlink {

template <class Config>
void declare_connection(ConfigSpec<Config>& c, std::string Config::*field, const std::string& description) {
  c.param("connection", field).describe(description);
  c.rule("connection is udpin://HOST:PORT, udpout://HOST:PORT or serial:///dev/PORT[:BAUD]", {"connection"},
         [field](const Config& config) { return valid_connection_url(config.*field); });
}

}  // namespace kestrel::mavlink
