// ParaView time series of a run (`softgrain run <scene> --vtk [--vtk-every N]`): VTK XML PolyData files
// (.vtp), one per dataset ("part") and frame, listed by a VTK XML Collection (<scene>.pvd) whose DataSet
// entries carry the frame's time value and part number.
//
// Format (VTK file formats, "XML File Formats"): VTKFile version 1.0, little-endian, header_type UInt64;
// arrays inline, either as text (ascii, 17 significant digits: values read back exactly) or as base64 of
// the byte count (UInt64) followed by the raw values ("binary", uncompressed, one base64 block: what VTK's
// own writer makes without compression). Points are 3D (z = 0 for 2D scenes); cells are vertices, lines
// (polylines) and polygons; cell data arrays list the vertices' values first, then the lines', then the
// polygons' (VTK's order of the cell kinds in PolyData). Point and cell arrays are Float64 (scalars,
// 3-vectors or 3 x 3 tensors of 9 components, row-major: T_xx T_xy T_xz T_yx ..., as VTK's tensors) or Int64
// (ids); field data (one tuple per array) holds a frame's scalars such as the load.
//
// A frame is written atomically: each file goes to `<name>.writing` and is renamed into place, and the
// collection is rewritten the same way after every frame, so it lists only complete frames at any moment.
#pragma once

#include "core/vector.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace softgrain::vtk {

enum class Encoding { ascii, base64 };

// One named array of a dataset: `components` values per tuple (1, 3 or 9), as doubles or as integers.
struct DataArray
{
    std::string name;
    int components = 1;
    bool integer = false; // Int64 (integers), else Float64 (reals)
    std::vector<double> reals;
    std::vector<std::int64_t> integers;
    std::size_t values() const { return integer ? integers.size() : reals.size(); }
};

// A PolyData dataset: points, cells (vertices, lines, polygons) and named point, cell and field data.
class PolyData
{
  public:
    // Appends a point (z = 0 in 2D) and returns its index.
    std::int64_t add_point(double x, double y, double z = 0.0);
    std::int64_t add_point(const Vec2& p) { return add_point(p.x(), p.y()); }
    // Cells over point indices: a vertex cell (one point), a polyline, a polygon (closed implicitly).
    void add_vertex(std::int64_t point);
    void add_line(const std::vector<std::int64_t>& points);
    void add_polygon(const std::vector<std::int64_t>& points);

    // Arrays: one value (or 3-vector) per point, per cell (vertices, then lines, then polygons), or one tuple
    // for the whole dataset. Sizes are checked when the file is made (std::logic_error: a defect).
    void point_scalars(std::string name, std::vector<double> values);
    void point_vectors(std::string name, std::vector<double> xyz);     // 3 per point
    void point_vectors(std::string name, const std::vector<Vec2>& xy); // z = 0
    void point_tensors(std::string name, std::vector<double> values);  // 9 per point, row-major
    void cell_scalars(std::string name, std::vector<double> values);
    void cell_ids(std::string name, std::vector<std::int64_t> values);
    void cell_vectors(std::string name, std::vector<double> xyz);
    void field(std::string name, double value);

    std::int64_t points() const { return static_cast<std::int64_t>(points_.size() / 3); }
    std::int64_t cells() const { return verts_.count() + lines_.count() + polys_.count(); }

    // The whole .vtp file.
    std::string xml(Encoding encoding = Encoding::base64) const;

  private:
    struct Cells
    {
        std::vector<std::int64_t> connectivity, offsets;
        std::int64_t count() const { return static_cast<std::int64_t>(offsets.size()); }
        void add(const std::vector<std::int64_t>& points);
    };
    void check_point(std::int64_t point) const;
    std::vector<double> points_;
    Cells verts_, lines_, polys_;
    std::vector<DataArray> point_data_, cell_data_, field_data_;
};

// `bytes` as base64 (RFC 4648, with padding).
std::string base64(const unsigned char* bytes, std::size_t size);

// A named dataset of a frame: its file is <name>_<frame, 6 digits>.vtp and its part number its position.
struct Part
{
    std::string name;
    PolyData data;
};

// A time series in one directory: frames written one after another, and the collection <name>.pvd.
class Series
{
  public:
    // every: --vtk-every (absent: the scene's own cadence).
    Series(std::filesystem::path directory, std::string name, std::optional<std::int64_t> every,
           Encoding encoding = Encoding::base64);

    // The frame cadence: --vtk-every if given, else the scene's default.
    std::int64_t every(std::int64_t scene_default = 1) const { return every_.value_or(scene_default); }
    // Whether opportunity `counter` (a time step or load step, counted from 0) makes a frame.
    bool due(std::int64_t counter, std::int64_t scene_default = 1) const
    {
        return counter % every(scene_default) == 0;
    }
    // Counts one opportunity (a recorded state, a load step) and tells whether it makes a frame: the first
    // and then every every(scene_default)-th. The count is part of state(), so it continues on resume.
    bool next(std::int64_t scene_default = 1) { return due(opportunities_++, scene_default); }
    // Writes one frame at time value `time` (simulation time, or the load step for quasi-static scenes).
    void write(double time, const std::vector<Part>& parts);

    int frames() const { return frames_; }
    double write_seconds() const { return write_seconds_; } // wall time spent writing frames
    std::uintmax_t bytes() const { return bytes_; }         // bytes of the frame files
    const std::filesystem::path& directory() const { return directory_; }
    std::filesystem::path collection() const { return directory_ / (name_ + ".pvd"); }

    // For checkpoints: the frames so far as bytes, and the series restored from them. Restoring removes
    // every file of the directory that is not a listed frame (frames written after the checkpoint, a
    // half-written file) and rewrites the collection; the next frame continues the numbering.
    std::string state() const;
    void restore(const std::string& state);

  private:
    struct Entry
    {
        double time = 0;
        std::int32_t frame = 0, part = 0;
        std::string name, file;
    };
    void write_collection() const;
    std::filesystem::path directory_;
    std::string name_;
    std::optional<std::int64_t> every_;
    Encoding encoding_;
    std::vector<Entry> entries_;
    int frames_ = 0;
    std::int64_t opportunities_ = 0;
    double write_seconds_ = 0;
    std::uintmax_t bytes_ = 0;
};

// Writes `content` to `path` atomically (`path`.writing, then a rename); a signal meanwhile removes the
// temporary file. IoError naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

} // namespace softgrain::vtk
