// /metrics: Prometheus text exposition of the render service's stats and the network counters.
#pragma once

#include <string>

#include "net/server_context.h"
#include "render/service/render_service.h"

namespace geodesic::net {

std::string prometheus_metrics(const ServiceStats& stats, const NetCounters& counters);

}  // namespace geodesic::net
