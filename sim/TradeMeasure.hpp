// One point of the trade measured (sim/TradePoints): it builds the point's
// configuration from the defaults and its overrides, runs it -- through the
// same Session `arpsim run` uses, the golden reference, the accuracy harness
// -- and returns its figures as JSON, the point's result file. A point is
// self-contained: any process on any machine can measure it.
#pragma once
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

#include "TradePoints.hpp"
#include "reference/accuracy/AccuracyHarness.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::sim {

// The point's configuration: the embedded defaults and its overrides, checked.
dp::ArpConfig trade_config(const TradePoint& p);

// Measures the point; `progress` (fraction, what) as it goes. Throws InputError
// (a bad override) or what the run throws; `scratch` is a folder for the run's
// own report, removed after. The result's "figures" hold the table's columns.
nlohmann::json measure_trade_point(const TradePoint& p, const TradeScale& s, const std::string& scratch,
                                   const std::function<void(double, const std::string&)>& progress = {});

// The accuracy harness's sample at each scale (the full one is `arpsim verify`'s default); the planner
// sizes widths with the quick one.
accuracy::Options accuracy_options(const TradeScale& s);

// The machine the figures were measured on ("AMD EPYC 9R14, 2 cores"), for result files and tables.
std::string machine_description();

}  // namespace arp::sim
