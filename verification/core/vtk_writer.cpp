// The VTK XML writer of `run --vtk` (core/vtk.hpp) against the format: base64 by the test vectors of RFC 4648
// section 10, a PolyData file's counts, offsets and arrays in the order VTK reads them, and a series whose
// collection lists only complete frames and is trimmed back to a checkpoint's frames on resume. That VTK's
// own reader accepts the files is checked by support/vtk_readback.py (test support.vtk_readback).
#include "core/vtk.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
namespace vtk = softgrain::vtk;

namespace {

std::string encode(const std::string& text)
{
    return vtk::base64(reinterpret_cast<const unsigned char*>(text.data()), text.size());
}

std::string read_text(const fs::path& path)
{
    std::ifstream in(path);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// The text between <DataArray ... Name="name" ...> and </DataArray>, whitespace-trimmed.
std::string array_text(const std::string& xml, const std::string& name)
{
    const std::regex pattern("<DataArray[^>]*Name=\"" + name + "\"[^>]*>\\s*([^<]*?)\\s*</DataArray>");
    std::smatch match;
    REQUIRE_MESSAGE(std::regex_search(xml, match, pattern), "no array " << name);
    return match[1].str();
}

int count(const std::string& text, const std::string& what)
{
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
        ++n;
    return n;
}

// A frame with a triangle, a polyline and a vertex: cell data in VTK's order, vertices, lines, polygons.
vtk::PolyData sample()
{
    vtk::PolyData data;
    const auto a = data.add_point(0, 0), b = data.add_point(1, 0), c = data.add_point(0.5, 0.25),
               d = data.add_point(2, 2);
    data.add_polygon({a, b, c});
    data.add_vertex(d);
    data.add_line({a, d});
    data.point_scalars("radius", {0.5, 0.5, 0.5, 0.125});
    data.point_vectors("velocity", {1, 2, 0, 0, 0, 0, 0, 0, 0, 0.1, 0.2, 0.3});
    data.cell_ids("particle_id", {7, 8, 9});
    data.cell_scalars("area_ratio", {0.1, 0.2, 1.0 / 3.0});
    data.field("strain", 0.25);
    return data;
}

} // namespace

TEST_CASE("base64 of the RFC 4648 test vectors [RFC 4648 sec. 10]")
{
    CHECK(encode("") == "");
    CHECK(encode("f") == "Zg==");
    CHECK(encode("fo") == "Zm8=");
    CHECK(encode("foo") == "Zm9v");
    CHECK(encode("foob") == "Zm9vYg==");
    CHECK(encode("fooba") == "Zm9vYmE=");
    CHECK(encode("foobar") == "Zm9vYmFy");
}

TEST_CASE("a PolyData file states its counts and lists cells and arrays as VTK reads them [VTK XML formats]")
{
    const std::string xml = sample().xml(vtk::Encoding::ascii);
    CHECK(xml.find("<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                   "header_type=\"UInt64\">") != std::string::npos);
    CHECK(xml.find("NumberOfPoints=\"4\" NumberOfVerts=\"1\" NumberOfLines=\"1\" NumberOfStrips=\"0\" "
                   "NumberOfPolys=\"1\"") != std::string::npos);
    CHECK(array_text(xml, "Points") == "0 0 0 1 0 0 0.5 0.25 0 2 2 0");
    // Connectivity and offsets of each kind, in the order Verts, Lines, Strips (empty), Polys.
    const std::regex connectivity("Name=\"connectivity\"[^>]*>\\s*([^<]*?)\\s*</DataArray>");
    std::vector<std::string> lists;
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), connectivity); it != std::sregex_iterator();
         ++it)
        lists.push_back((*it)[1].str());
    REQUIRE(lists.size() == 4);
    CHECK(lists[0] == "3");
    CHECK(lists[1] == "0 3");
    CHECK(lists[2] == "");
    CHECK(lists[3] == "0 1 2");
    // 17 significant digits: a double survives the text exactly.
    CHECK(array_text(xml, "area_ratio") == "0.10000000000000001 0.20000000000000001 0.33333333333333331");
    CHECK(array_text(xml, "particle_id") == "7 8 9");
    CHECK(xml.find("<DataArray type=\"Int64\" Name=\"particle_id\" NumberOfComponents=\"1\"") !=
          std::string::npos);
    CHECK(xml.find("<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"") !=
          std::string::npos);
    CHECK(xml.find("Name=\"strain\" NumberOfTuples=\"1\" NumberOfComponents=\"1\"") != std::string::npos);
    // The first scalar and vector arrays are the active ones.
    CHECK(xml.find("<PointData Scalars=\"radius\" Vectors=\"velocity\">") != std::string::npos);
    CHECK(xml.find("<CellData Scalars=\"particle_id\">") != std::string::npos);
}

TEST_CASE("binary arrays are base64 of the UInt64 byte count and the little-endian values [VTK XML formats]")
{
    vtk::PolyData data;
    data.add_vertex(data.add_point(1.0, -2.0, 0.5));
    const std::string xml = data.xml(vtk::Encoding::base64);
    const double values[3] = {1.0, -2.0, 0.5};
    unsigned char bytes[8 + sizeof values];
    const std::uint64_t size = sizeof values;
    std::memcpy(bytes, &size, 8);
    std::memcpy(bytes + 8, values, sizeof values);
    CHECK(array_text(xml, "Points") == vtk::base64(bytes, sizeof bytes));
    CHECK(xml.find("format=\"ascii\"") == std::string::npos);
}

TEST_CASE("a 9-component point array is a row-major tensor, the active tensors [VTK XML formats]")
{
    vtk::PolyData data;
    data.add_vertex(data.add_point(0, 0, 0));
    data.add_vertex(data.add_point(1, 0, 0));
    data.point_scalars("pressure", {1.0, 2.0});
    data.point_tensors("deformation_gradient", {1, 2, 3, 4, 5, 6, 7, 8, 9, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    data.point_tensors("cauchy_stress", std::vector<double>(18, 0.5));
    const std::string xml = data.xml(vtk::Encoding::ascii);
    CHECK(xml.find("<DataArray type=\"Float64\" Name=\"deformation_gradient\" NumberOfComponents=\"9\"") !=
          std::string::npos);
    CHECK(array_text(xml, "deformation_gradient") == "1 2 3 4 5 6 7 8 9 1 0 0 0 1 0 0 0 1");
    CHECK(xml.find("<PointData Scalars=\"pressure\" Tensors=\"deformation_gradient\">") != std::string::npos);
    // 9 values per point: 17 values for two points are refused.
    vtk::PolyData short_of_one;
    short_of_one.add_vertex(short_of_one.add_point(0, 0, 0));
    short_of_one.add_vertex(short_of_one.add_point(1, 0, 0));
    short_of_one.point_tensors("F", std::vector<double>(17, 1.0));
    CHECK_THROWS_AS(static_cast<void>(short_of_one.xml()), std::logic_error);
}

TEST_CASE("an array of the wrong size is a defect, refused when the file is made")
{
    vtk::PolyData data;
    data.add_polygon({data.add_point(0, 0), data.add_point(1, 0), data.add_point(0, 1)});
    data.point_scalars("radius", {1.0, 2.0});
    CHECK_THROWS_AS(static_cast<void>(data.xml()), std::logic_error);
    vtk::PolyData cells;
    cells.add_point(0, 0);
    CHECK_THROWS_AS(cells.add_line({0, 1}), std::logic_error); // point 1 does not exist
}

TEST_CASE("a series lists complete frames only and resumes from a checkpoint's frames")
{
    const fs::path dir = fs::temp_directory_path() / ("softgrain-vtk-" + std::to_string(getpid()));
    fs::remove_all(dir);
    vtk::Series series(dir, "scene", std::nullopt, vtk::Encoding::ascii);
    CHECK(series.every(5) == 5);
    const auto frame = [&](double t) { series.write(t, {{"particles", sample()}, {"walls", sample()}}); };
    frame(0.0);
    frame(0.5);
    const std::string checkpoint = series.state();
    frame(1.0);
    CHECK(series.frames() == 3);
    CHECK(count(read_text(series.collection()), "<DataSet ") == 6);
    CHECK(fs::exists(dir / "walls_000002.vtp"));
    for (const auto& entry : fs::directory_iterator(dir))
        CHECK(entry.path().extension() != ".writing");

    // A run resumed from the checkpoint taken after two frames: the third is gone, the numbering continues.
    vtk::Series resumed(dir, "scene", std::nullopt, vtk::Encoding::ascii);
    std::ofstream(dir / "particles_000003.vtp.writing") << "half"; // killed while writing
    resumed.restore(checkpoint);
    CHECK(resumed.frames() == 2);
    CHECK_FALSE(fs::exists(dir / "particles_000002.vtp"));
    CHECK_FALSE(fs::exists(dir / "particles_000003.vtp.writing"));
    const std::string pvd = read_text(resumed.collection());
    CHECK(count(pvd, "<DataSet ") == 4);
    CHECK(pvd.find(
              "<DataSet timestep=\"0.5\" group=\"\" part=\"1\" name=\"walls\" file=\"walls_000001.vtp\"/>") !=
          std::string::npos);
    resumed.write(1.0, {{"particles", sample()}});
    CHECK(fs::exists(dir / "particles_000002.vtp"));
    CHECK(count(read_text(resumed.collection()), "<DataSet ") == 5);

    // The cadence: the first opportunity and every third after it.
    vtk::Series thinned(dir / "thinned", "scene", 3);
    std::string made;
    for (int k = 0; k < 7; ++k)
        made += thinned.next(1) ? '1' : '0';
    CHECK(made == "1001001");
    fs::remove_all(dir);
}
