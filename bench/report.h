// report.h — docs/BENCHMARKS.md: the machine, the targets and whether each scene meets them (and
// by how much not, and why), the suite, mesh setup, and the run time against error sweep.
#pragma once

#include "device_table.h"
#include "end_to_end.h"
#include "error_sweep.h"
#include "geometry_change.h"
#include "moving_object.h"
#include "points.h"
#include "shadows.h"
#include "machine.h"
#include "mesh_load.h"
#include "scene_bench.h"

#include <string>
#include <vector>

namespace phongvk::bench {

struct Report {
  std::string command;   // the one command that regenerates the report
  bool quick = false;
  std::string only;      // the run was limited to scenes whose name has this
  int repeat = 0;
  std::string revision;  // git revision of the sources, when known
  Machine machine;
  std::vector<SceneResult> scenes;
  DeviceTable devices;   // each device and key path (device_table.h)
  std::vector<SetupResult> setups;
  SweepResult sweep;
  EndToEnd endToEnd;
  std::vector<MeshLoadRun> meshLoads;
  std::vector<GeometryChangeRun> geometryChanges;
  std::vector<MovingObjectRun> movingObjects;
  std::vector<ShadowRun> shadows;
  std::vector<PointsRun> points;
  ShadowBuild shadowBuild;
  std::string plotLink;  // the plot, relative to the report; empty when there is none
  std::string plotNote;  // why there is no plot
};

// The whole markdown document.
std::string formatReport(const Report& report);

}  // namespace phongvk::bench
