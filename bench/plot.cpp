#include "plot.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>

namespace phongvk::bench {

namespace {

namespace fs = std::filesystem;

using Filter = std::function<bool(const SweepPoint&)>;

struct Series {
  std::string title, style;
  Filter keep;
  bool labelled;   // points carry their setting ("s32", "k3")
  bool staircase;  // a corner between consecutive points, so a line through them draws steps
};

std::string dataLine(const std::string& label, double cost, double rmse) {
  return label + " " + std::to_string(cost) + " " + std::to_string(rmse) + "\n";
}

// One gnuplot data block: "label cost rmse" per point of the series, by cost.
std::string dataBlock(const SweepResult& sweep, const Series& series) {
  std::vector<const SweepPoint*> points;
  for (const SweepPoint& p : sweep.points) {
    if (p.compute.ok() && series.keep(p)) points.push_back(&p);
  }
  std::sort(points.begin(), points.end(), [](auto* a, auto* b) { return a->cost() < b->cost(); });
  std::string text;
  for (size_t i = 0; i < points.size(); ++i) {
    if (series.staircase && i > 0) text += dataLine("-", points[i]->cost(), points[i - 1]->computeError.rmse);
    text += dataLine(points[i]->label, points[i]->cost(), points[i]->computeError.rmse);
  }
  return text;
}

// gnuplot's single-quoted strings escape a quote by doubling it.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}


std::string script(const SweepResult& sweep, const std::vector<Series>& series, const std::string& data,
                   const std::string& png, const std::string& deviceName) {
  std::string s = "set terminal pngcairo size 960,640 font ',11'\nset output " + quoted(png) + "\n";
  s += "set title " + quoted("Sphere under one light, " + std::to_string(sweep.width) + "x" +
                             std::to_string(sweep.height) + ": compute frame against error (" + deviceName + ")") + "\n";
  s += "set xlabel 'compute frame, device ms (median)'\nset ylabel 'RMSE against the analytic ground truth (8-bit units)'\n";
  s += "set logscale xy\nset grid\nset key top right\n";
  std::string plot = "plot ";
  for (size_t i = 0; i < series.size(); ++i) {
    const std::string block = quoted(data) + " index " + std::to_string(i);
    plot += block + " using 2:3 " + series[i].style + " title " + quoted(series[i].title) + ", ";
    if (series[i].labelled) plot += block + " using 2:3:1 with labels offset char 1.2,0.6 font ',9' notitle, ";
  }
  return s + plot.substr(0, plot.size() - 2) + "\n";
}

}  // namespace

std::string plotErrorSweep(const SweepResult& sweep, const std::string& pngPath, const std::string& deviceName) {
  // The front is drawn as a staircase: at any cost, the least error some setting reaches for it.
  // A series per shading mode and sample count, both meshes in it (labels s32: UV segments, k3:
  // icosphere subdivisions).
  auto mode = [](std::string shading, int samples) -> Filter {
    return [=](const SweepPoint& p) { return p.shading == shading && p.samples == samples; };
  };
  const std::vector<Series> all = {
      {"flat", "with points pt 9 ps 1.3 lc rgb '#1b9e77'", mode("flat", 1), true, false},
      {"Gouraud", "with points pt 7 ps 1.3 lc rgb '#d95f02'", mode("Gouraud", 1), true, false},
      {"Phong", "with points pt 5 ps 1.3 lc rgb '#7570b3'", mode("Phong", 1), true, false},
      {"Gouraud, 4 samples", "with points pt 6 ps 1.3 lc rgb '#d95f02'", mode("Gouraud", 4), false, false},
      {"Phong, 4 samples", "with points pt 4 ps 1.3 lc rgb '#7570b3'", mode("Phong", 4), false, false},
      {"Pareto front", "with lines lw 2 dt 2 lc rgb '#505050'", [](const SweepPoint& p) { return p.pareto; }, false, true},
  };
  // Empty blocks would shift gnuplot's block indices; series without points are left out.
  std::vector<Series> series;
  std::string data;
  for (const Series& s : all) {
    const std::string block = dataBlock(sweep, s);
    if (block.empty()) continue;
    series.push_back(s);
    data += block + "\n\n";
  }
  if (series.empty()) return "no compute frame was measured";
  const fs::path dir = fs::temp_directory_path() / ("phongvk_bench_plot_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "sweep.dat") << data;
  std::ofstream(dir / "sweep.gp") << script(sweep, series, (dir / "sweep.dat").string(), pngPath, deviceName);
  // The paths are this process's own temporary folder (no quotes in them), so gnuplot's quoting
  // serves the shell too.
  const std::string command = "gnuplot " + quoted((dir / "sweep.gp").string()) + " 2>" + quoted((dir / "log").string());
  const int status = std::system(command.c_str());
  std::ifstream log(dir / "log");
  const std::string why((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  fs::remove_all(dir);
  // gnuplot's last message line says what went wrong; the lines before it echo the script.
  const size_t last = why.find_last_of('\n', why.size() >= 2 ? why.size() - 2 : 0);
  if (status != 0) return "gnuplot failed: " + (last == std::string::npos ? why : why.substr(last + 1));
  return "";
}

}  // namespace phongvk::bench
