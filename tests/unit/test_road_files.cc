// The road files scanners and profilometers write: X3P (ISO 25178-72) and
// ISO 13473-1 text profiles. The references are files composed here byte by
// byte from the standard's layout, with their MD5 sums computed beforehand by
// an independent program (Python's hashlib), and closed forms: linear
// interpolation of missing points, the MPD of a cosine.
#include "scratch.h"

#include <greentread/base/exceptions.h>
#include <greentread/road/texture.h>
#include <greentread/road/texture_files.h>

#include <boost/test/unit_test.hpp>

#include <minizip/zip.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace greentread;

namespace
{
  /// A zip archive of @p members (name, bytes), stored uncompressed.
  void
  write_zip(const std::string                                      &file,
            const std::vector<std::pair<std::string, std::string>> &members)
  {
    zipFile zip = zipOpen64(file.c_str(), APPEND_STATUS_CREATE);
    BOOST_REQUIRE(zip);
    for (const auto &[name, bytes] : members)
      {
        zip_fileinfo info{};
        BOOST_REQUIRE(zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0,
                                            nullptr, 0, 0, 0) == ZIP_OK);
        BOOST_REQUIRE(zipWriteInFileInZip(zip, bytes.data(), bytes.size()) == ZIP_OK);
        BOOST_REQUIRE(zipCloseFileInZip(zip) == ZIP_OK);
      }
    BOOST_REQUIRE(zipClose(zip, nullptr) == ZIP_OK);
  }

  /// An 8 x 4 surface of int16 heights, z = -0.5 mm + raw um, points 5 and
  /// 15 cleared in valid.bin, in a top-level folder as some writers zip it,
  /// with prefixed and unprefixed elements. The MD5 sums are hashlib's.
  const std::vector<int> raw = {-400, -30, 340, -300, 70,  440, -200, 170, 540, -100, 270,
                                -370, 0,   370, -270, 100, 470, -170, 200, 570, -70,  300,
                                -340, 30,  400, -240, 130, 500, -140, 230, 600, -40};
  const std::string      main_xml =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n"
    "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType>\n"
    "<Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1.0E-4</Increment>"
    "<Offset>0</Offset></CX>\n"
    "<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2.5E-4</Increment></CY>\n"
    "<CZ><AxisType>A</AxisType><DataType>I</DataType><Increment>1.0E-6</Increment>"
    "<Offset>-5.0E-4</Offset></CZ></Axes></Record1>\n"
    "<Record2><Date>N/A</Date></Record2>\n"
    "<Record3><MatrixDimension><SizeX>8</SizeX><SizeY>4</SizeY><SizeZ>1</SizeZ>"
    "</MatrixDimension>\n"
    "<DataLink><p:PointDataLink>bindata/data.bin</p:PointDataLink><MD5ChecksumPointData>"
    "7021C03CECC6EAB58E2D2EAFCAAD95D1</MD5ChecksumPointData>\n"
    "<ValidPointsLink>bindata/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>"
    "9245f98854034c0df50f2e22d570c599</MD5ChecksumValidPoints></DataLink></Record3>\n"
    "<Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>\n"
    "</p:ISO5436_2>\n";
  const std::string main_xml_md5 = "8d4e17b8bfae133ec6cfdac52234606b";

  std::string
  int16_data(const std::vector<int> &values)
  {
    std::string bytes;
    for (const int v : values)
      {
        const std::int16_t s = static_cast<std::int16_t>(v);
        bytes += static_cast<char>(s & 0xff);
        bytes += static_cast<char>((s >> 8) & 0xff);
      }
    return bytes;
  }

  const std::string valid_bits = {'\xdf', '\x7f', '\xff', '\xff'};

  /// The composed file, with @p data and @p checksum_file in place of the
  /// right ones when given.
  std::string
  composed(const std::filesystem::path &dir,
           const std::string           &name,
           const std::string           &data,
           const std::string           &checksum_file)
  {
    const std::string file = (dir / name).string();
    write_zip(file, {{"scan/main.xml", main_xml},
                     {"scan/md5checksum.hex", checksum_file},
                     {"scan/bindata/data.bin", data},
                     {"scan/bindata/valid.bin", valid_bits},
                     {"__MACOSX/scan/._main.xml", "junk"}});
    return file;
  }

  template <typename F>
  std::string
  input_error(F &&f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "(no error)";
  }
} // namespace

BOOST_AUTO_TEST_SUITE(road_files)

BOOST_AUTO_TEST_CASE(composed_x3p_with_int16_heights_and_missing_points)
{
  const auto dir        = test::scratch_directory("composed_x3p");
  const auto file       = composed(dir, "scan.x3p", int16_data(raw), main_xml_md5 + " *main.xml\n");
  const road::Texture t = road::read_texture(file);
  BOOST_TEST(t.nx == 8u);
  BOOST_TEST(t.ny == 4u);
  BOOST_TEST(t.dx == 1e-4);
  BOOST_TEST(t.dy == 2.5e-4);
  const auto height = [](const int r) {
    return -5e-4 + r * 1e-6;
  };
  for (std::size_t k = 0; k < raw.size(); ++k)
    {
      // Point 5 lies between 4 and 6 of its profile; point 15 ends the
      // second profile and takes its neighbour 14.
      const double expected = k == 5  ? 0.5 * (height(raw[4]) + height(raw[6])) :
                              k == 15 ? height(raw[14]) :
                                        height(raw[k]);
      BOOST_TEST(t.z[k] == expected, boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(wrong_checksums_are_refused)
{
  const auto dir = test::scratch_directory("x3p_checksums");
  // The bare hex, as some writers give it, is accepted.
  BOOST_CHECK_NO_THROW(
    road::read_x3p(composed(dir, "bare.x3p", int16_data(raw), main_xml_md5 + "\n")));
  const std::string main_error = input_error([&] {
    road::read_x3p(composed(dir, "xml.x3p", int16_data(raw), "0123456789abcdef0123456789abcdef"));
  });
  BOOST_TEST(main_error.find("MD5 sum of main.xml is " + main_xml_md5) != std::string::npos,
             main_error);
  auto changed = raw;
  changed[9] += 1;
  const std::string data_error = input_error([&] {
    road::read_x3p(composed(dir, "data.x3p", int16_data(changed), main_xml_md5));
  });
  BOOST_TEST(data_error.find("MD5 sum of bindata/data.bin") != std::string::npos, data_error);
}

BOOST_AUTO_TEST_CASE(every_data_type_round_trips)
{
  const auto                       dir = test::scratch_directory("x3p_types");
  road::Texture                    t;
  std::mt19937                     random(7);
  std::normal_distribution<double> normal(0., 2e-3);
  t.nx = 40;
  t.ny = 7;
  t.dx = 5e-4;
  t.dy = 1e-3;
  for (unsigned int k = 0; k < t.nx * t.ny; ++k)
    t.z.push_back(normal(random));
  // Missing: a profile's first point, an interior one, two in a row, a last.
  std::vector<bool> valid(t.z.size(), true);
  for (const unsigned int k : {0u, 57u, 120u, 121u, 199u})
    valid[k] = false;
  const auto interpolated = [&](const unsigned int k) {
    const unsigned int i = k % t.nx, row = k - i;
    unsigned int       a = i, b = i;
    while (a > 0 && !valid[row + a])
      --a;
    while (b + 1 < t.nx && !valid[row + b])
      ++b;
    if (!valid[row + a])
      return t.z[row + b];
    if (!valid[row + b])
      return t.z[row + a];
    return t.z[row + a] + (t.z[row + b] - t.z[row + a]) * double(i - a) / (b - a);
  };
  const auto [lo, hi] = std::minmax_element(t.z.begin(), t.z.end());
  for (const char type : {'I', 'L', 'F', 'D'})
    {
      const std::string file = (dir / (std::string("t_") + type + ".x3p")).string();
      road::write_x3p(file, t, type, valid);
      const road::Texture r = road::read_texture(file);
      BOOST_TEST(r.nx == t.nx);
      BOOST_TEST(r.ny == t.ny);
      BOOST_TEST(r.dx == t.dx);
      BOOST_TEST(r.dy == t.dy);
      // The type's resolution: int16 spans the range in 65000 steps (half a
      // step of rounding), int32 in 4.2e9, float32 half an ulp.
      const double step  = (*hi - *lo) / 65000.;
      const double bound = type == 'I' ? 0.5 * step :
                           type == 'L' ? 0.5 * step * 65000. / 4.2e9 + 1e-18 :
                           type == 'F' ? 6e-8 * std::max(-*lo, *hi) :
                                         0.;
      double       worst = 0.;
      for (unsigned int k = 0; k < t.z.size(); ++k)
        {
          const double expected = valid[k] ? t.z[k] : interpolated(k);
          worst                 = std::max(worst, std::abs(r.z[k] - expected));
        }
      BOOST_TEST_MESSAGE("X3P type " << type << ": worst height error " << worst << " m, bound "
                                     << bound);
      BOOST_TEST(worst <= bound * 1.0001 + 1e-300);
      if (type == 'I')
        BOOST_TEST(worst >= 0.3 * bound); // the rounding is really there
    }
}

BOOST_AUTO_TEST_CASE(inline_data_list_and_refused_features)
{
  const auto        dir  = test::scratch_directory("x3p_list");
  const std::string head = "<?xml version=\"1.0\"?>\n<ISO5436_2><Record1><FeatureType>";
  const auto        xml  = [&](const std::string &feature, const std::string &type,
                       const std::string &cx_axis) {
    return head + feature + "</FeatureType><Axes><CX><AxisType>" + cx_axis +
           "</AxisType><Increment>1e-3</Increment></CX><CY><AxisType>I</AxisType>"
                   "<Increment>1e-3</Increment></CY><CZ><AxisType>A</AxisType><DataType>" +
           type +
           "</DataType></CZ></Axes></Record1><Record3><MatrixDimension><SizeX>3</SizeX>"
                   "<SizeY>4</SizeY><SizeZ>1</SizeZ></MatrixDimension><DataList>"
                   "<Datum>1e-3</Datum><Datum>2e-3</Datum><Datum>3e-3</Datum>"
                   "<Datum>4e-3</Datum><Datum/><Datum>6e-3</Datum>"
                   "<Datum>1e-3</Datum><Datum>1e-3</Datum><Datum>1e-3</Datum>"
                   "<Datum>0</Datum><Datum>0</Datum><Datum>-1e-3</Datum>"
                   "</DataList></Record3></ISO5436_2>\n";
  };
  const std::string good = (dir / "list.x3p").string();
  write_zip(good, {{"main.xml", xml("SUR", "D", "I")}});
  const road::Texture t = road::read_x3p(good);
  BOOST_TEST(t.nx == 3u);
  BOOST_TEST(t.ny == 4u);
  BOOST_TEST(t.z[4] == 5e-3, boost::test_tools::tolerance(1e-12)); // between 4 and 6 mm
  BOOST_TEST(t.z[11] == -1e-3);

  const auto refused = [&](const std::string &name, const std::string &text) {
    const std::string file = (dir / name).string();
    write_zip(file, {{"main.xml", text}});
    return input_error([&] {
      road::read_x3p(file);
    });
  };
  const std::string type_error = refused("type.x3p", xml("SUR", "C", "I"));
  BOOST_TEST(type_error.find("Record1/Axes/CZ/DataType = 'C'; allowed: I (int16), L (int32), "
                             "F (float32), D (float64)") != std::string::npos,
             type_error);
  const std::string cloud_error = refused("cloud.x3p", xml("PCL", "D", "I"));
  BOOST_TEST(cloud_error.find("FeatureType = 'PCL'") != std::string::npos, cloud_error);
  const std::string axis_error = refused("axis.x3p", xml("SUR", "D", "A"));
  BOOST_TEST(axis_error.find("CX/AxisType = 'A'") != std::string::npos, axis_error);

  std::ofstream(dir / "not_a_zip.x3p") << "PK\x03\x04 but no archive";
  const std::string zip_error = input_error([&] {
    road::read_x3p((dir / "not_a_zip.x3p").string());
  });
  BOOST_TEST(zip_error.find("is not a zip archive") != std::string::npos, zip_error);
}

BOOST_AUTO_TEST_CASE(too_many_missing_points_are_refused)
{
  road::Texture t;
  t.nx = 10;
  t.ny = 2;
  t.dx = t.dy = 1e-3;
  t.z.assign(20, 1e-3);
  t.z[3] = t.z[4] = NAN;
  BOOST_TEST(road::fill_missing(t, "ten_percent") == 2u); // 10% is allowed
  t.z[3] = t.z[4] = t.z[15] = NAN;
  const std::string error   = input_error([&] {
    road::fill_missing(t, "fifteen_percent");
  });
  BOOST_TEST(error.find("3 of its 20 heights are missing; allowed: at most 10%") !=
               std::string::npos,
             error);
}

BOOST_AUTO_TEST_CASE(iso_13473_text_profile)
{
  // A cosine of 2 mm amplitude and 25 mm wavelength at 1 mm spacing over
  // 400 mm, sampled at the cells' centres, heights in mm; two dropouts away
  // from the peaks. Its MPD is the amplitude: each half segment's peak is
  // near A, and the segment's mean is 0.
  const auto          dir = test::scratch_directory("text_profile");
  const double        A = 2., lambda = 25.;
  std::ofstream       out(dir / "cosine.mm");
  std::vector<double> heights;
  out.precision(17);
  out << "profile_name: cosine\nsample_spacing_mm: 1.0\n";
  for (int i = 0; i < 400; ++i)
    {
      heights.push_back(A * std::cos(2. * M_PI * (i + 0.5) / lambda));
      if (i == 30 || i == 131)
        out << "NaN\n";
      else
        out << heights.back() << "\n";
    }
  out.close();
  const road::Texture t = road::read_texture((dir / "cosine.mm").string());
  BOOST_TEST(t.nx == 400u);
  BOOST_TEST(t.ny == 1u);
  BOOST_TEST(t.dx == 1e-3);
  for (const int i : {0, 29, 200, 399})
    BOOST_TEST(t.z[i] == 1e-3 * heights[i], boost::test_tools::tolerance(1e-6));
  for (const int i : {30, 131})
    BOOST_TEST(t.z[i] == 0.5e-3 * (heights[i - 1] + heights[i + 1]),
               boost::test_tools::tolerance(1e-6));
  // The peaks sampled at the cells' centres fall short of A by at most
  // A (1 - cos(pi / 25)) = 0.016 mm.
  const double mpd = road::mean_profile_depth(t);
  BOOST_TEST(mpd <= A * 1e-3 + 1e-12);
  BOOST_TEST(mpd >= A * 1e-3 * std::cos(M_PI / lambda) - 1e-12);

  // Heights in um instead of mm span 4000 "mm": refused.
  std::ofstream(dir / "in_um.mm") << "sample_spacing_mm: 1.0\n1500\n-2500\n300\n";
  const std::string error = input_error([&] {
    road::read_texture((dir / "in_um.mm").string());
  });
  BOOST_TEST(error.find("span 4000 mm from valley to peak; allowed: 0.01 mm to 100 mm") !=
               std::string::npos,
             error);
}

BOOST_AUTO_TEST_SUITE_END()
