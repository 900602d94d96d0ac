/// @file turning_profile.cpp
/// @brief Allowance profiles from records.
#include "machining/turning_profile.hpp"

#include "io/record_fields.hpp"
#include "io/record_reader.hpp"

namespace tk::machining {

std::vector<AllowanceSegment> read_profile(const std::string& path) {
  io::RecordReader reader({path});
  reader.expect_columns({{"z_from", "z_to", "depth"}, {"z", "depth"}});
  std::vector<AllowanceSegment> profile;
  Record record;
  bool segments_shape = false, first = true;
  double previous_z = 0, previous_depth = 0;
  Location previous_where;
  const auto check_depth = [](double depth, const Location& where) {
    if (!(depth >= 0 && depth < 50)) throw Error("depth must be in [0, 50) mm", where);
  };
  while (reader.next(record)) {
    const Location where = reader.where();
    if (first) segments_shape = record.contains("z_from");
    if (segments_shape) {
      AllowanceSegment s{io::number_field(record, "z_from", where), io::number_field(record, "z_to", where),
                         io::number_field(record, "depth", where)};
      if (!(s.z_from_mm < s.z_to_mm)) throw Error("z_to must be greater than z_from", where);
      if (!first && s.z_from_mm != profile.back().z_to_mm)
        throw Error("z_from must be where the segment before ends", where);
      check_depth(s.depth_mm, where);
      profile.push_back(s);
    } else {
      const double z = io::number_field(record, "z", where);
      if (!first) {
        if (!(z > previous_z)) throw Error("z must increase from record to record", where);
        // Only the last record may go without a depth; which one is last
        // shows when another follows.
        if (previous_depth < 0) throw Error("missing field 'depth'", previous_where);
        profile.push_back({previous_z, z, previous_depth});
      }
      const auto depth = io::optional_number_field(record, "depth", where);
      if (depth) check_depth(*depth, where);
      previous_depth = depth ? *depth : -1;
      previous_z = z;
      previous_where = where;
    }
    first = false;
  }
  if (profile.empty()) {
    const std::string name = path == "-" ? "<stdin>" : path;
    throw Error(segments_shape ? "the profile has no segment"
                               : "the profile needs at least two records (z, depth), the last ending the cut",
                {name, 0});
  }
  return profile;
}

}  // namespace tk::machining
