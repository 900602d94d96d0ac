/// @file bench.cpp
/// @brief tnorm-bench bench: the inference timed per t-norm.
#include <cmath>

#include "fuzzy/inference_timing.hpp"
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"

namespace tnorm_bench {

using namespace tk;

void run_bench(cli::ToolApp& tool, const ControllerOptions& options, double seconds) {
  io::RecordWriter writer(tool.output_format());
  const auto triples = fuzzy::protocol_triples(options.adc_bits);
  for (TNorm t : options.chosen_tnorms(true)) {
    const fuzzy::Engine engine = options.engine(t);
    if (engine.inputs.size() != 3) throw Error("bench needs a controller with three inputs (the sensors)");
    fuzzy::Mamdani controller = options.controller(engine);
    const fuzzy::InferenceTiming timing = fuzzy::time_inferences(controller, triples, seconds);
    const fuzzy::Defuzzifier& d = engine.outputs[0].defuzzifier;
    Record r;
    r["tnorm"] = tnorm_label(engine);
    r["ns_per_inference"] = std::round(timing.ns_per_inference * 10) / 10;
    r["ms_per_2x1024"] = std::round(timing.ms_per_2x1024 * 1e4) / 1e4;
    r["inferences"] = timing.inferences;
    r["centroid"] = d.kind == fuzzy::Defuzzifier::Kind::exact ? "exact" : "discrete";
    r["resolution"] = d.kind == fuzzy::Defuzzifier::Kind::exact ? Record() : Record(d.resolution);
    writer.write(r);
    writer.flush();
  }
}

}  // namespace tnorm_bench
