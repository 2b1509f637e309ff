#include "core/vtk.hpp"

#include "core/checkpoint.hpp"
#include "core/errors.hpp"
#include "core/leftovers.hpp"

#include <bit>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

namespace softgrain::vtk {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "the VTK files declare byte_order LittleEndian");

namespace {

void append_real(std::string& out, double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    out += text;
}

// One <DataArray>: its attributes, then the values (as text or as base64 of the byte count and the bytes).
void write_array(std::string& out, const DataArray& array, Encoding encoding, const std::string& indent)
{
    out += indent + "<DataArray type=\"" + (array.integer ? "Int64" : "Float64") + "\"";
    if (!array.name.empty()) out += " Name=\"" + array.name + "\"";
    out += " NumberOfComponents=\"" + std::to_string(array.components) + "\" format=\"" +
           (encoding == Encoding::ascii ? "ascii" : "binary") + "\">\n" + indent + "  ";
    if (encoding == Encoding::ascii) {
        for (std::size_t i = 0; i < array.values(); ++i) {
            if (i) out += ' ';
            if (array.integer)
                out += std::to_string(array.integers[i]);
            else
                append_real(out, array.reals[i]);
        }
    } else {
        const std::uint64_t size = array.values() * 8; // Int64 and Float64 alike
        std::vector<unsigned char> bytes(sizeof size + size);
        std::memcpy(bytes.data(), &size, sizeof size);
        if (size > 0)
            std::memcpy(bytes.data() + sizeof size,
                        array.integer ? static_cast<const void*>(array.integers.data())
                                      : static_cast<const void*>(array.reals.data()),
                        size);
        out += base64(bytes.data(), bytes.size());
    }
    out += "\n" + indent + "</DataArray>\n";
}

DataArray integer_array(std::string name, std::vector<std::int64_t> values)
{
    DataArray a{std::move(name), 1, true, {}, std::move(values)};
    return a;
}

DataArray real_array(std::string name, int components, std::vector<double> values)
{
    return DataArray{std::move(name), components, false, std::move(values), {}};
}

void check_size(const DataArray& array, std::int64_t tuples, const std::string& where)
{
    if (array.values() != static_cast<std::size_t>(tuples) * static_cast<std::size_t>(array.components))
        throw std::logic_error("VTK " + where + " array '" + array.name + "' has " +
                               std::to_string(array.values()) + " values for " + std::to_string(tuples) +
                               " tuples of " + std::to_string(array.components));
}

// The first array of each kind is the active one (ParaView colours by it by default).
std::string active_attributes(const std::vector<DataArray>& arrays)
{
    std::string scalars, vectors, tensors;
    for (const DataArray& a : arrays) {
        if (a.components == 1 && scalars.empty()) scalars = a.name;
        if (a.components == 3 && vectors.empty()) vectors = a.name;
        if (a.components == 9 && tensors.empty()) tensors = a.name;
    }
    std::string out;
    if (!scalars.empty()) out += " Scalars=\"" + scalars + "\"";
    if (!vectors.empty()) out += " Vectors=\"" + vectors + "\"";
    if (!tensors.empty()) out += " Tensors=\"" + tensors + "\"";
    return out;
}

std::string frame_file(const std::string& part, int frame)
{
    std::ostringstream name;
    name << part << "_" << std::setw(6) << std::setfill('0') << frame << ".vtp";
    return name.str();
}

} // namespace

std::string base64(const unsigned char* bytes, std::size_t size)
{
    static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (std::size_t i = 0; i < size; i += 3) {
        const std::uint32_t b0 = bytes[i], b1 = i + 1 < size ? bytes[i + 1] : 0u,
                            b2 = i + 2 < size ? bytes[i + 2] : 0u;
        const std::uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
        out += alphabet[(triple >> 18) & 63];
        out += alphabet[(triple >> 12) & 63];
        out += i + 1 < size ? alphabet[(triple >> 6) & 63] : '=';
        out += i + 2 < size ? alphabet[triple & 63] : '=';
    }
    return out;
}

std::int64_t PolyData::add_point(double x, double y, double z)
{
    points_.insert(points_.end(), {x, y, z});
    return points() - 1;
}

void PolyData::Cells::add(const std::vector<std::int64_t>& points)
{
    connectivity.insert(connectivity.end(), points.begin(), points.end());
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
}

void PolyData::check_point(std::int64_t point) const
{
    if (point < 0 || point >= points())
        throw std::logic_error("VTK cell refers to point " + std::to_string(point) + " of " +
                               std::to_string(points()));
}

void PolyData::add_vertex(std::int64_t point)
{
    check_point(point);
    verts_.add({point});
}

void PolyData::add_line(const std::vector<std::int64_t>& points)
{
    for (const std::int64_t p : points)
        check_point(p);
    lines_.add(points);
}

void PolyData::add_polygon(const std::vector<std::int64_t>& points)
{
    for (const std::int64_t p : points)
        check_point(p);
    polys_.add(points);
}

void PolyData::point_scalars(std::string name, std::vector<double> values)
{
    point_data_.push_back(real_array(std::move(name), 1, std::move(values)));
}

void PolyData::point_vectors(std::string name, std::vector<double> xyz)
{
    point_data_.push_back(real_array(std::move(name), 3, std::move(xyz)));
}

void PolyData::point_vectors(std::string name, const std::vector<Vec2>& xy)
{
    std::vector<double> xyz;
    xyz.reserve(3 * xy.size());
    for (const Vec2& v : xy)
        xyz.insert(xyz.end(), {v.x(), v.y(), 0.0});
    point_vectors(std::move(name), std::move(xyz));
}

void PolyData::point_tensors(std::string name, std::vector<double> values)
{
    point_data_.push_back(real_array(std::move(name), 9, std::move(values)));
}

void PolyData::cell_scalars(std::string name, std::vector<double> values)
{
    cell_data_.push_back(real_array(std::move(name), 1, std::move(values)));
}

void PolyData::cell_ids(std::string name, std::vector<std::int64_t> values)
{
    cell_data_.push_back(integer_array(std::move(name), std::move(values)));
}

void PolyData::cell_vectors(std::string name, std::vector<double> xyz)
{
    cell_data_.push_back(real_array(std::move(name), 3, std::move(xyz)));
}

void PolyData::field(std::string name, double value)
{
    field_data_.push_back(real_array(std::move(name), 1, {value}));
}

std::string PolyData::xml(Encoding encoding) const
{
    for (const DataArray& a : point_data_)
        check_size(a, points(), "point");
    for (const DataArray& a : cell_data_)
        check_size(a, cells(), "cell");
    std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                      "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PolyData>\n";
    if (!field_data_.empty()) {
        out += "    <FieldData>\n";
        for (const DataArray& a : field_data_) {
            // Field arrays are tuples without a dataset: their size is stated.
            std::string one;
            write_array(one, a, encoding, "      ");
            const auto at = one.find(" NumberOfComponents");
            one.insert(at, " NumberOfTuples=\"1\"");
            out += one;
        }
        out += "    </FieldData>\n";
    }
    out += "    <Piece NumberOfPoints=\"" + std::to_string(points()) + "\" NumberOfVerts=\"" +
           std::to_string(verts_.count()) + "\" NumberOfLines=\"" + std::to_string(lines_.count()) +
           "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(polys_.count()) + "\">\n";
    out += "      <PointData" + active_attributes(point_data_) + ">\n";
    for (const DataArray& a : point_data_)
        write_array(out, a, encoding, "        ");
    out += "      </PointData>\n      <CellData" + active_attributes(cell_data_) + ">\n";
    for (const DataArray& a : cell_data_)
        write_array(out, a, encoding, "        ");
    out += "      </CellData>\n      <Points>\n";
    write_array(out, real_array("Points", 3, points_), encoding, "        ");
    out += "      </Points>\n";
    const auto cells = [&](const char* tag, const Cells& c) {
        out += std::string("      <") + tag + ">\n";
        write_array(out, integer_array("connectivity", c.connectivity), encoding, "        ");
        write_array(out, integer_array("offsets", c.offsets), encoding, "        ");
        out += std::string("      </") + tag + ">\n";
    };
    cells("Verts", verts_);
    cells("Lines", lines_);
    cells("Strips", Cells{});
    cells("Polys", polys_);
    out += "    </Piece>\n  </PolyData>\n</VTKFile>\n";
    return out;
}

void write_file_atomically(const fs::path& path, const std::string& content)
{
    const fs::path temporary = path.string() + ".writing";
    remove_on_signal(temporary);
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (out) out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (out.fail()) {
        const std::string reason = std::strerror(errno);
        std::error_code ignored;
        fs::remove(temporary, ignored);
        keep_on_signal(temporary);
        throw IoError("cannot write " + temporary.string() + ": " + reason);
    }
    fs::rename(temporary, path);
    keep_on_signal(temporary);
}

Series::Series(fs::path directory, std::string name, std::optional<std::int64_t> every, Encoding encoding)
    : directory_(std::move(directory)), name_(std::move(name)), every_(every), encoding_(encoding)
{
    fs::create_directories(directory_);
}

void Series::write(double time, const std::vector<Part>& parts)
{
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const std::string file = frame_file(parts[k].name, frames_);
        const std::string content = parts[k].data.xml(encoding_);
        write_file_atomically(directory_ / file, content);
        bytes_ += content.size();
        entries_.push_back({time, frames_, static_cast<std::int32_t>(k), parts[k].name, file});
    }
    ++frames_;
    write_collection();
    write_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Series::write_collection() const
{
    std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                      "byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (const Entry& e : entries_) {
        out += "    <DataSet timestep=\"";
        append_real(out, e.time);
        out += "\" group=\"\" part=\"" + std::to_string(e.part) + "\" name=\"" + e.name + "\" file=\"" +
               e.file + "\"/>\n";
    }
    out += "  </Collection>\n</VTKFile>\n";
    write_file_atomically(collection(), out);
}

namespace {
struct SavedEntry
{
    double time;
    std::int32_t frame, part;
    std::string name, file;
    void transfer(Archive& archive)
    {
        archive(time);
        archive(frame);
        archive(part);
        archive(name);
        archive(file);
    }
};
} // namespace

std::string Series::state() const
{
    std::vector<SavedEntry> saved;
    for (const Entry& e : entries_)
        saved.push_back({e.time, e.frame, e.part, e.name, e.file});
    std::int32_t frames = frames_;
    std::uint64_t bytes = bytes_;
    std::ostringstream out(std::ios::binary);
    Archive archive(out);
    std::int64_t opportunities = opportunities_;
    archive(frames);
    archive(opportunities);
    archive(bytes);
    archive(saved);
    return out.str();
}

void Series::restore(const std::string& state)
{
    entries_.clear();
    frames_ = 0;
    opportunities_ = 0;
    bytes_ = 0;
    if (!state.empty()) {
        std::istringstream in(state, std::ios::binary);
        Archive archive(in, state.size());
        std::int32_t frames = 0;
        std::uint64_t bytes = 0;
        std::vector<SavedEntry> saved;
        archive(frames);
        archive(opportunities_);
        archive(bytes);
        archive(saved);
        frames_ = frames;
        bytes_ = bytes;
        for (SavedEntry& e : saved)
            entries_.push_back({e.time, e.frame, e.part, std::move(e.name), std::move(e.file)});
    }
    std::set<std::string> listed{collection().filename().string()};
    for (const Entry& e : entries_)
        listed.insert(e.file);
    for (const auto& entry : fs::directory_iterator(directory_))
        if (!listed.count(entry.path().filename().string())) fs::remove_all(entry.path());
    for (const Entry& e : entries_)
        if (!fs::is_regular_file(directory_ / e.file))
            throw InputError(
                "--resume --vtk: the frame " + (directory_ / e.file).string() +
                " of the checkpoint is missing; allowed: resuming with the frames the checkpoint "
                "lists, or deleting the checkpoint to start afresh");
    write_collection();
}

} // namespace softgrain::vtk
