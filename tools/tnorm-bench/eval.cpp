/// @file eval.cpp
/// @brief tnorm-bench eval: the controller's motor commands added to
/// records of sensor readings.
#include <fmt/format.h>

#include <cmath>

#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"

namespace tnorm_bench {

using namespace tk;

void run_eval(cli::ToolApp& tool, const ControllerOptions& options) {
  const std::vector<TNorm> chosen = options.chosen_tnorms(false);
  if (chosen.size() > 1) throw UsageError("eval takes one --tnorm");
  const fuzzy::Engine engine = options.engine(chosen.empty() ? std::nullopt : std::optional<TNorm>(chosen[0]));
  fuzzy::Mamdani controller = options.controller(engine);
  const bool paper_controller = options.fll_path.empty();
  const double full_scale = options.adc_bits == 10 ? 1023 : 4095;
  io::RecordReader reader(tool.common().inputs);
  std::vector<std::string> input_names;
  for (const auto& input : engine.inputs) input_names.push_back(input.name);
  reader.expect_columns({input_names});
  io::RecordWriter writer(tool.output_format());
  std::vector<std::string> added;
  for (const auto& out : engine.outputs) added.push_back(out.name);
  writer.declare_fields(added);
  std::vector<double> in(engine.inputs.size()), out(engine.outputs.size());
  Record record;
  while (reader.next(record)) {
    const Location where = reader.where();
    for (std::size_t i = 0; i < in.size(); ++i) {
      in[i] = io::number_field(record, engine.inputs[i].name, where);
      if (paper_controller && (in[i] < 0 || in[i] > full_scale))
        throw Error(fmt::format("{} reading {} is outside the {}-bit ADC's 0..{}", engine.inputs[i].name, in[i],
                                options.adc_bits, full_scale),
                    where);
    }
    controller.evaluate(in, out);
    for (std::size_t o = 0; o < out.size(); ++o) {
      if (std::isnan(out[o])) record[engine.outputs[o].name] = nullptr;  // no rule fired and the default is nan
      else record[engine.outputs[o].name] = out[o];
    }
    writer.write(record);
  }
  writer.flush();
}

}  // namespace tnorm_bench
