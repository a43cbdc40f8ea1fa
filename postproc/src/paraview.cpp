// ParaView time series (.pvd + .vtu) through vtkXMLUnstructuredGridWriter.
#include <brash/post/paraview.hpp>

#include <fmt/format.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <brash/run/run_layout.hpp>
#ifdef BRASH_POST_HAVE_HULL
#include <brash/hull/mesh.hpp>
#endif

namespace brash::post {
namespace fs = std::filesystem;
namespace {

vtkNew<vtkDoubleArray> array(const char* name, int comps, std::size_t n) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(static_cast<vtkIdType>(n));
  return a;
}

void write_grid(vtkUnstructuredGrid* grid, const fs::path& path) {
  const auto tmp = brash::run::temp_path_for(path);
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetFileName(tmp.string().c_str());
  w->SetInputData(grid);
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();  // raw binary, zlib-compressed (default compressor): compact, meshio-readable
  if (w->Write() != 1) throw std::runtime_error("VTK could not write " + tmp.string());
  fs::rename(tmp, path);
}

void write_particles(const Snapshot& s, const fs::path& path) {
  const auto n = s.size();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(n));
  auto radius = array("radius", 1, n), vel = array("velocity", 3, n), sub = array("submerged_fraction", 1, n),
       ca = array("ca", 3, n);
  vtkNew<vtkIdTypeArray> id;
  id->SetName("id");
  id->SetNumberOfTuples(static_cast<vtkIdType>(n));
  vtkNew<vtkCellArray> cells;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<vtkIdType>(i);
    pts->SetPoint(k, s.x[i], s.y[i], s.z[i]);
    radius->SetValue(k, s.radius[i]);
    vel->SetTuple3(k, s.vx[i], s.vy[i], s.vz[i]);
    sub->SetValue(k, s.submerged_fraction[i]);
    ca->SetTuple3(k, s.ca_x[i], s.ca_y[i], s.ca_z[i]);
    id->SetValue(k, static_cast<vtkIdType>(s.id[i]));
    cells->InsertNextCell(1, &k);
  }
  vtkNew<vtkUnstructuredGrid> g;
  g->SetPoints(pts);
  g->SetCells(VTK_VERTEX, cells);
  for (vtkDataArray* a : {static_cast<vtkDataArray*>(radius), static_cast<vtkDataArray*>(vel),
                          static_cast<vtkDataArray*>(sub), static_cast<vtkDataArray*>(ca), static_cast<vtkDataArray*>(id)})
    g->GetPointData()->AddArray(a);
  if (!s.active.empty()) {  // 1 integrated, 0 idle far-field ice (files without the column: no field)
    auto active = array("active", 1, n);
    for (std::size_t i = 0; i < n; ++i) active->SetValue(static_cast<vtkIdType>(i), s.active[i]);
    g->GetPointData()->AddArray(active);
  }
  if (!s.state.empty()) {  // the moving window: 0 in the scene, 1 held out, 2 removed (brash/post/particles.hpp)
    auto state = array("state", 1, n);
    for (std::size_t i = 0; i < n; ++i) state->SetValue(static_cast<vtkIdType>(i), s.state[i]);
    g->GetPointData()->AddArray(state);
  }
  g->GetPointData()->SetActiveScalars("radius");
  write_grid(g, path);
}

vtkNew<vtkUnstructuredGrid> hull_grid(const HullSurface& h, double dx, double dz) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  const auto nv = h.xyz.size() / 3;
  pts->SetNumberOfPoints(static_cast<vtkIdType>(nv));
  for (std::size_t i = 0; i < nv; ++i)
    pts->SetPoint(static_cast<vtkIdType>(i), h.xyz[3 * i] + dx, h.xyz[3 * i + 1], h.xyz[3 * i + 2] + dz);
  vtkNew<vtkCellArray> cells;
  for (std::size_t t = 0; t + 2 < h.tri.size(); t += 3) {
    const vtkIdType ids[3] = {h.tri[t], h.tri[t + 1], h.tri[t + 2]};
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkUnstructuredGrid> g;
  g->SetPoints(pts);
  g->SetCells(VTK_TRIANGLE, cells);
  return g;
}

void write_hull(const HullSurface& h, double dx, double dz, const fs::path& path) {
  write_grid(hull_grid(h, dx, dz), path);
}

}  // namespace

std::optional<HullSurface> load_case_hull(const PostCase& c, std::vector<std::string>& notes) {
#ifdef BRASH_POST_HAVE_HULL
  try {
    const auto m = brash::hull::read_mesh(c.hull_file);
    HullSurface h;
    for (const auto& v : m.vertices) h.xyz.insert(h.xyz.end(), {v.x(), v.y(), v.z()});
    for (const auto& f : m.faces) h.tri.insert(h.tri.end(), {f[0], f[1], f[2]});
    return h;
  } catch (const std::exception& e) {
    notes.push_back(fmt::format("ParaView: no hull series ({})", e.what()));
    return std::nullopt;
  }
#else
  (void)c;
  notes.push_back("ParaView: no hull series (brash_hull not built in)");
  return std::nullopt;
#endif
}

fs::path write_hull_contact_field(const fs::path& run_dir, const HullSurface& hull,
                                  const std::vector<double>& contact_fraction,
                                  const std::vector<double>& contact_pressure_Pa) {
  auto g = hull_grid(hull, 0, 0);
  const auto add = [&](const char* name, const std::vector<double>& v) {
    if (v.empty()) return;
    auto a = array(name, 1, v.size());
    for (std::size_t i = 0; i < v.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), v[i]);
    g->GetCellData()->AddArray(a);
  };
  add("contact_fraction", contact_fraction);
  add("contact_pressure_Pa", contact_pressure_Pa);
  g->GetCellData()->SetActiveScalars(contact_pressure_Pa.empty() ? "contact_fraction" : "contact_pressure_Pa");
  const auto path = run_dir / "hull.vtu";
  write_grid(g, path);
  return path;
}

std::string pvd_text(const std::vector<std::pair<double, std::string>>& items) {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& [t, f] : items) s += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, f);
  return s + "  </Collection>\n</VTKFile>\n";
}

ParaviewOutput write_paraview(const fs::path& run_dir, const std::vector<SnapshotEntry>& entries,
                              const std::optional<HullSurface>& hull, const PostCase& c, bool run_in_progress,
                              std::vector<std::string>& notes) {
  ParaviewOutput out;
  const auto dir = run_dir / "paraview";
  fs::create_directories(dir);
  std::vector<std::pair<double, std::string>> parts, hulls;
  for (const auto& e : entries) {
    if (!fs::exists(e.file)) {
      notes.push_back(fmt::format("ParaView: snapshot {} listed in particles/index.csv is missing: skipped", e.file.string()));
      continue;
    }
    const auto s = read_snapshot(e, run_in_progress, Pieces::All);  // the whole channel, its state in a field
    const auto pname = fmt::format("particles_{}.vtu", e.step);
    write_particles(s, dir / pname);
    parts.emplace_back(e.t_s, "paraview/" + pname);
    if (hull) {
      const auto hname = fmt::format("hull_{}.vtu", e.step);
      write_hull(*hull, e.hull_x_m, c.water_level_m - c.draft_m, dir / hname);
      hulls.emplace_back(e.t_s, "paraview/" + hname);
    }
  }
  out.snapshots = parts.size();
  out.particles_pvd = run_dir / "particles.pvd";
  brash::run::write_atomic(out.particles_pvd, pvd_text(parts));
  if (hull) {
    out.hull_pvd = run_dir / "hull.pvd";
    brash::run::write_atomic(out.hull_pvd, pvd_text(hulls));
  }
  return out;
}

}  // namespace brash::post
