/// @file bench_dxf_parse.cpp
/// @brief The DXF reader (read_dxf_file: the file into memory, tags,
/// entities to segments) against python3-ezdxf's ezdxf.readfile on the same
/// generated ~32 MB R2000 file of LINE, ARC and LWPOLYLINE entities, in the
/// same run. ezdxf is timed inside python around readfile alone (CPU time),
/// so the interpreter's start-up is left out. Goal: ours at least 20 times
/// faster. Prints MB/s of both.
#include <unistd.h>

#include <array>
#include <cstdio>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "cad/dxf_reader.hpp"

namespace {

constexpr double kGoal = 20;

/// Writes the file and returns its path; `entities` gets how many it holds.
std::string write_drawing(std::size_t target_bytes, std::size_t& entities) {
  char path[] = "/tmp/bench_dxf_parse_XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0) bench::fail("mkstemp");
  FILE* out = fdopen(fd, "w");
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> coordinate(-500, 500), radius(1, 50), angle(0, 360), bulge(-1, 1);
  std::fprintf(out, "  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1015\n  9\n$INSUNITS\n 70\n4\n  0\nENDSEC\n");
  std::fprintf(out, "  0\nSECTION\n  2\nENTITIES\n");
  unsigned handle = 0x100;
  entities = 0;
  const char* layers[] = {"0", "outline", "holes", "pockets"};
  while (std::ftell(out) < static_cast<long>(target_bytes)) {
    const char* layer = layers[entities % 4];
    switch (entities % 3) {
      case 0:
        std::fprintf(out,
                     "  0\nLINE\n  5\n%X\n330\n1F\n100\nAcDbEntity\n  8\n%s\n100\nAcDbLine\n"
                     " 10\n%.6f\n 20\n%.6f\n 30\n0.0\n 11\n%.6f\n 21\n%.6f\n 31\n0.0\n",
                     handle++, layer, coordinate(random), coordinate(random), coordinate(random), coordinate(random));
        break;
      case 1:
        std::fprintf(out,
                     "  0\nARC\n  5\n%X\n330\n1F\n100\nAcDbEntity\n  8\n%s\n100\nAcDbCircle\n"
                     " 10\n%.6f\n 20\n%.6f\n 30\n0.0\n 40\n%.6f\n100\nAcDbArc\n 50\n%.6f\n 51\n%.6f\n",
                     handle++, layer, coordinate(random), coordinate(random), radius(random), angle(random),
                     angle(random));
        break;
      default: {
        const int vertices = 12;
        std::fprintf(out,
                     "  0\nLWPOLYLINE\n  5\n%X\n330\n1F\n100\nAcDbEntity\n  8\n%s\n100\nAcDbPolyline\n"
                     " 90\n%d\n 70\n1\n 43\n0.0\n",
                     handle++, layer, vertices);
        for (int v = 0; v < vertices; ++v) {
          std::fprintf(out, " 10\n%.6f\n 20\n%.6f\n", coordinate(random), coordinate(random));
          if (v % 3 == 0) std::fprintf(out, " 42\n%.6f\n", bulge(random));
        }
      }
    }
    ++entities;
  }
  std::fprintf(out, "  0\nENDSEC\n  0\nEOF\n");
  std::fclose(out);
  return path;
}

/// CPU seconds of ezdxf.readfile on `path` as python measures them, and the
/// number of entities ezdxf found in the model space.
std::pair<double, std::size_t> ezdxf_readfile(const std::string& path) {
  const std::string command =
      "/usr/bin/python3 -c 'import sys, time, ezdxf\n"
      "t = time.process_time(); doc = ezdxf.readfile(sys.argv[1]); t = time.process_time() - t\n"
      "print(t, len(doc.modelspace()))' " +
      path + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) bench::fail("cannot run: " + command);
  std::string output;
  std::array<char, 256> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe.get())) output += buffer.data();
  std::istringstream fields(output);
  double seconds = -1;
  std::size_t entities = 0;
  if (!(fields >> seconds >> entities) || seconds <= 0) bench::fail("unexpected output from python3-ezdxf: " + output);
  return {seconds, entities};
}

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_DXF_PARSE_REPEATS", "BENCH_REPEATS"}, 3);
  std::size_t entities = 0;
  const std::string path = write_drawing(32u << 20, entities);
  FILE* file = std::fopen(path.c_str(), "rb");
  std::fseek(file, 0, SEEK_END);
  const double megabytes = static_cast<double>(std::ftell(file)) / 1e6;
  std::fclose(file);
  std::printf("bench_dxf_parse: read_dxf_file vs python3-ezdxf ezdxf.readfile, %.1f MB, %zu entities, %d repeats\n",
              megabytes, entities, repeats);

  bench::Results results("bench_dxf_parse");
  std::vector<double> ours_rate, peer_rate;
  for (int r = 0; r < repeats; ++r) {
    // ours, ezdxf, ours: a machine that drifts affects both sides alike.
    tk::cad::Drawing drawing;
    const double a = bench::time_cpu([&] { drawing = tk::cad::read_dxf_file(path); });
    const auto [peer, peer_entities] = ezdxf_readfile(path);
    const double b = bench::time_cpu([&] { drawing = tk::cad::read_dxf_file(path); });
    std::size_t read = 0;
    for (const auto& [type, count] : drawing.entities_read) read += count;
    if (read != entities || peer_entities != entities)
      bench::fail("entities: generated " + std::to_string(entities) + ", ours " + std::to_string(read) + ", ezdxf " +
                  std::to_string(peer_entities));
    const double ours = (a + b) / 2;
    ours_rate.push_back(megabytes / ours);
    peer_rate.push_back(megabytes / peer);
    results.add(ours, peer);
  }
  results.report(kGoal);
  std::printf("FIGURE dxf_mb_per_s_ours %.1f MB/s (%zu segments a run)\n", bench::median(ours_rate),
              tk::cad::read_dxf_file(path).segments.size());
  std::printf("FIGURE dxf_mb_per_s_ezdxf %.2f MB/s\n", bench::median(peer_rate));
  std::remove(path.c_str());
  return 0;
}
