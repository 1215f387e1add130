#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/road/texture_files.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <minizip/unzip.h>
#include <minizip/zip.h>
#include <openssl/evp.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace greentread
{
  namespace road
  {
    namespace
    {
      using boost::property_tree::ptree;

      /// The MD5 sum of @p bytes, 32 lowercase hexadecimal digits.
      std::string
      md5(const std::string &bytes)
      {
        unsigned char digest[EVP_MAX_MD_SIZE];
        unsigned int  length = 0;
        if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_md5(), nullptr) != 1)
          throw NumericalError("MD5: OpenSSL's digest failed");
        static const char hex[] = "0123456789abcdef";
        std::string       text;
        for (unsigned int i = 0; i < length; ++i)
          {
            text += hex[digest[i] >> 4];
            text += hex[digest[i] & 15];
          }
        return text;
      }

      std::string
      lower(std::string s)
      {
        std::transform(s.begin(), s.end(), s.begin(), [](const unsigned char c) {
          return static_cast<char>(std::tolower(c));
        });
        return s;
      }


      /// The members of an X3P archive, read whole.
      class Archive
      {
      public:
        explicit Archive(const std::string &file)
            : file(file)
            , zip(unzOpen64(file.c_str()), &unzClose)
        {
          if (!zip)
            throw InputError("X3P file '" + file +
                             "' is not a zip archive (an X3P file is one, holding main.xml)");
          for (int s = unzGoToFirstFile(zip.get()); s == UNZ_OK; s = unzGoToNextFile(zip.get()))
            {
              unz_file_info64 info;
              char            name[1024];
              if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof(name), nullptr, 0, nullptr,
                                          0) != UNZ_OK)
                throw InputError("X3P file '" + file + "': its zip directory cannot be read");
              const std::string n(name);
              if (!n.empty() && n.back() != '/')
                names.push_back(n);
            }
          // main.xml at the root or in one top-level folder (some writers
          // zip the folder), not in a packer's side folder.
          if (std::find(names.begin(), names.end(), "main.xml") == names.end())
            {
              std::vector<std::string> folders;
              for (const auto &n : names)
                {
                  const auto slash = n.find('/');
                  if (n.rfind("__MACOSX/", 0) != 0 && slash != std::string::npos &&
                      n.substr(slash + 1) == "main.xml")
                    folders.push_back(n.substr(0, slash + 1));
                }
              if (folders.size() > 1)
                throw InputError("X3P file '" + file + "' holds " + std::to_string(folders.size()) +
                                 " main.xml files in different folders; allowed: one");
              if (folders.size() == 1)
                folder = folders.front();
            }
          if (std::find(names.begin(), names.end(), folder + "main.xml") == names.end())
            throw InputError("X3P file '" + file + "' holds no main.xml (ISO 25178-72)");
        }

        bool
        has(const std::string &member) const
        {
          return std::find(names.begin(), names.end(), folder + member) != names.end();
        }

        /// The bytes of @p member, a path relative to main.xml's folder.
        std::string
        read(const std::string &member) const
        {
          if (!has(member) || unzLocateFile(zip.get(), (folder + member).c_str(), 1) != UNZ_OK)
            throw InputError("X3P file '" + file + "': main.xml links to '" + member +
                             "', which the archive does not hold");
          unz_file_info64 info;
          unzGetCurrentFileInfo64(zip.get(), &info, nullptr, 0, nullptr, 0, nullptr, 0);
          if (unzOpenCurrentFile(zip.get()) != UNZ_OK)
            throw InputError("X3P file '" + file + "': member '" + member +
                             "' cannot be opened (allowed compression: stored or deflate)");
          std::string bytes(info.uncompressed_size, '\0');
          const int   got =
            bytes.empty() ? 0 : unzReadCurrentFile(zip.get(), bytes.data(), bytes.size());
          const int closed = unzCloseCurrentFile(zip.get());
          if (got != static_cast<int>(bytes.size()) || closed != UNZ_OK)
            throw InputError("X3P file '" + file + "': member '" + member +
                             "' is truncated or corrupt (its CRC does not match)");
          return bytes;
        }

      private:
        std::string                                file;
        std::unique_ptr<void, decltype(&unzClose)> zip;
        std::vector<std::string>                   names;
        std::string                                folder;
      };

      /// The name of @p key without its namespace prefix.
      std::string
      local_name(const std::string &key)
      {
        const auto colon = key.find(':');
        return colon == std::string::npos ? key : key.substr(colon + 1);
      }

      /// The child of @p tree named @p name (any prefix), or nullptr.
      const ptree *
      child(const ptree &tree, const std::string &name)
      {
        for (const auto &[key, sub] : tree)
          if (local_name(key) == name)
            return &sub;
        return nullptr;
      }

      const ptree &
      required(const ptree &tree, const std::string &path, const std::string &file)
      {
        const ptree *t    = &tree;
        std::string  rest = path, done;
        while (!rest.empty())
          {
            const auto slash = rest.find('/');
            const auto name  = rest.substr(0, slash);
            rest             = slash == std::string::npos ? "" : rest.substr(slash + 1);
            done += (done.empty() ? "" : "/") + name;
            t = child(*t, name);
            if (!t)
              throw InputError("X3P file '" + file + "': main.xml has no element " + done);
          }
        return *t;
      }

      std::string
      text_of(const ptree &tree, const std::string &name, const std::string &fallback)
      {
        const ptree *c = child(tree, name);
        if (!c)
          return fallback;
        const std::string t = base::trim(c->data());
        return t.empty() ? fallback : t;
      }

      double
      number_of(const ptree       &tree,
                const std::string &name,
                const double       fallback,
                const std::string &where,
                const std::string &file)
      {
        const std::string t = text_of(tree, name, "");
        if (t.empty())
          return fallback;
        char        *end = nullptr;
        const double v   = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0' || !std::isfinite(v))
          throw InputError("X3P file '" + file + "': " + where + "/" + name + " = '" + t +
                           "' is not a number");
        return v;
      }

      /// Bytes of one value of an X3P data type, 0 if not one.
      std::size_t
      size_of(const char type)
      {
        switch (type)
          {
            case 'I':
              return 2;
            case 'L':
            case 'F':
              return 4;
            case 'D':
              return 8;
            default:
              return 0;
          }
      }

      /// Value @p k of the little-endian data @p bytes of @p type.
      double
      value_at(const std::string &bytes, const std::size_t k, const char type)
      {
        const char *p = bytes.data() + k * size_of(type);
        switch (type)
          {
            case 'I':
              {
                std::int16_t v;
                std::memcpy(&v, p, 2);
                return v;
              }
            case 'L':
              {
                std::int32_t v;
                std::memcpy(&v, p, 4);
                return v;
              }
            case 'F':
              {
                float v;
                std::memcpy(&v, p, 4);
                return v;
              }
            default:
              {
                double v;
                std::memcpy(&v, p, 8);
                return v;
              }
          }
      }

      void
      check_sum(const ptree       &link,
                const std::string &element,
                const std::string &bytes,
                const std::string &member,
                const std::string &file)
      {
        const std::string expected = lower(text_of(link, element, ""));
        if (expected.empty())
          return;
        const std::string actual = md5(bytes);
        if (actual != expected)
          throw InputError("X3P file '" + file + "': the MD5 sum of " + member + " is " + actual +
                           ", but main.xml's " + element + " says " + expected +
                           " (the file is damaged or was changed after it was written)");
      }
    } // namespace



    Texture
    read_x3p(const std::string &file)
    {
      const Archive     archive(file);
      const std::string xml = archive.read("main.xml");

      // md5checksum.hex: the MD5 of main.xml, as md5sum prints it.
      if (archive.has("md5checksum.hex"))
        {
          std::istringstream sum(archive.read("md5checksum.hex"));
          std::string        expected;
          sum >> expected;
          if (lower(expected) != md5(xml))
            throw InputError("X3P file '" + file + "': the MD5 sum of main.xml is " + md5(xml) +
                             ", but md5checksum.hex says '" + expected +
                             "' (the file is damaged or was changed after it was written)");
        }

      ptree root;
      try
        {
          std::istringstream in(xml);
          boost::property_tree::read_xml(in, root);
        }
      catch (const boost::property_tree::xml_parser_error &e)
        {
          throw InputError("X3P file '" + file + "': main.xml is not well-formed XML, line " +
                           std::to_string(e.line()) + ": " + e.message());
        }
      const ptree *top = child(root, "ISO5436_2");
      if (!top)
        top = child(root, "ISO5436");
      if (!top)
        throw InputError("X3P file '" + file + "': main.xml's root is not ISO5436_2");

      const ptree      &record1 = required(*top, "Record1", file);
      const std::string feature = text_of(record1, "FeatureType", "");
      if (feature != "SUR" && feature != "PRF")
        throw InputError("X3P file '" + file + "': Record1/FeatureType = '" + feature +
                         "'; allowed: SUR (a surface) or PRF (a profile), not a point cloud");
      const ptree &axes = required(record1, "Axes", file);
      const ptree &cx   = required(axes, "CX", file);
      const ptree &cy   = required(axes, "CY", file);
      const ptree &cz   = required(axes, "CZ", file);
      for (const auto &[name, axis] :
           {std::pair<std::string, const ptree *>{"CX", &cx}, {"CY", &cy}})
        if (text_of(*axis, "AxisType", "I") != "I")
          throw InputError("X3P file '" + file + "': Record1/Axes/" + name + "/AxisType = '" +
                           text_of(*axis, "AxisType", "") +
                           "'; allowed: I (incremental: a regular grid)");
      const std::string type_name = text_of(cz, "DataType", "");
      const char        type      = type_name.size() == 1 ? type_name[0] : '?';
      if (size_of(type) == 0)
        throw InputError("X3P file '" + file + "': Record1/Axes/CZ/DataType = '" + type_name +
                         "'; allowed: I (int16), L (int32), F (float32), D (float64)");
      const double z_increment = number_of(cz, "Increment", 1., "Record1/Axes/CZ", file);
      const double z_offset    = number_of(cz, "Offset", 0., "Record1/Axes/CZ", file);

      const ptree &record3 = required(*top, "Record3", file);
      const ptree &size    = required(record3, "MatrixDimension", file);
      const double nx      = number_of(size, "SizeX", 0., "Record3/MatrixDimension", file);
      const double ny      = number_of(size, "SizeY", 1., "Record3/MatrixDimension", file);
      const double nz      = number_of(size, "SizeZ", 1., "Record3/MatrixDimension", file);
      if (nz != 1.)
        throw InputError("X3P file '" + file + "': Record3/MatrixDimension/SizeZ = " +
                         format_short(nz) + "; allowed: 1 (one layer of heights)");
      if (!(nx >= 2.) || !(ny >= 1.) || nx * ny > 4e9)
        throw InputError("X3P file '" + file + "': " + format_short(nx) + " x " + format_short(ny) +
                         " points; allowed: at least 2 x 1");

      Texture t;
      t.nx = static_cast<unsigned int>(nx);
      t.ny = static_cast<unsigned int>(ny);
      t.dx = number_of(cx, "Increment", 0., "Record1/Axes/CX", file);
      t.dy = t.ny == 1 ? t.dx : number_of(cy, "Increment", 0., "Record1/Axes/CY", file);
      const std::size_t n = std::size_t(t.nx) * t.ny;
      t.z.assign(n, std::numeric_limits<double>::quiet_NaN());

      if (const ptree *link = child(record3, "DataLink"))
        {
          const std::string member = text_of(*link, "PointDataLink", "");
          const std::string data   = archive.read(member);
          check_sum(*link, "MD5ChecksumPointData", data, member, file);
          if (data.size() != n * size_of(type))
            throw InputError("X3P file '" + file + "': " + member + " holds " +
                             std::to_string(data.size()) + " bytes; " + std::to_string(t.nx) +
                             " x " + std::to_string(t.ny) + " heights of type " + type_name +
                             " need " + std::to_string(n * size_of(type)));
          for (std::size_t k = 0; k < n; ++k)
            t.z[k] = z_offset + value_at(data, k, type) * z_increment;
          const std::string valid_member = text_of(*link, "ValidPointsLink", "");
          if (!valid_member.empty())
            {
              const std::string bits = archive.read(valid_member);
              check_sum(*link, "MD5ChecksumValidPoints", bits, valid_member, file);
              if (bits.size() < (n + 7) / 8)
                throw InputError("X3P file '" + file + "': " + valid_member + " holds " +
                                 std::to_string(bits.size()) + " bytes; " + std::to_string(n) +
                                 " points need " + std::to_string((n + 7) / 8));
              for (std::size_t k = 0; k < n; ++k)
                if (!((static_cast<unsigned char>(bits[k / 8]) >> (k % 8)) & 1u))
                  t.z[k] = std::numeric_limits<double>::quiet_NaN();
            }
        }
      else if (const ptree *list = child(record3, "DataList"))
        {
          std::size_t k = 0;
          for (const auto &[key, datum] : *list)
            {
              if (local_name(key) != "Datum")
                continue;
              if (k == n)
                throw InputError("X3P file '" + file + "': Record3/DataList holds more than " +
                                 std::to_string(n) + " Datum elements");
              const std::string value = base::trim(datum.data());
              if (!value.empty())
                {
                  char        *end = nullptr;
                  const double v   = std::strtod(value.c_str(), &end);
                  if (end == value.c_str() || *end != '\0')
                    throw InputError("X3P file '" + file + "': Datum " + std::to_string(k + 1) +
                                     " = '" + value + "' is not a number");
                  t.z[k] = z_offset + v * z_increment;
                }
              ++k;
            }
          if (k != n)
            throw InputError("X3P file '" + file + "': Record3/DataList holds " +
                             std::to_string(k) + " Datum elements; " + std::to_string(n) +
                             " points need as many");
        }
      else
        throw InputError("X3P file '" + file + "': Record3 has neither DataLink nor DataList");

      fill_missing(t, file);
      return t;
    }



    void
    write_x3p(const std::string       &file,
              const Texture           &t,
              const char               type,
              const std::vector<bool> &valid)
    {
      if (size_of(type) == 0)
        throw InputError("X3P file '" + file + "': data type '" + std::string(1, type) +
                         "'; allowed: I, L, F, D");
      const std::size_t n = t.z.size();
      if (!valid.empty() && valid.size() != n)
        throw InputError("X3P file '" + file + "': " + std::to_string(valid.size()) +
                         " validity flags for " + std::to_string(n) + " heights");
      const auto is_valid = [&](const std::size_t k) {
        return valid.empty() || valid[k];
      };

      // Integer heights span the type's range: z = offset + value increment.
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (std::size_t k = 0; k < n; ++k)
        if (is_valid(k))
          {
            lo = std::min(lo, t.z[k]);
            hi = std::max(hi, t.z[k]);
          }
      const double range     = hi > lo ? hi - lo : 1e-6;
      const double increment = type == 'I' ? range / 65000. : type == 'L' ? range / 4.2e9 : 1.;
      const double offset    = (type == 'I' || type == 'L') ? 0.5 * (lo + hi) : 0.;

      std::string data(n * size_of(type), '\0'), bits((n + 7) / 8, '\xff');
      for (std::size_t k = 0; k < n; ++k)
        {
          char *p = data.data() + k * size_of(type);
          if (!is_valid(k))
            bits[k / 8] = static_cast<char>(bits[k / 8] & ~(1u << (k % 8)));
          const double z = is_valid(k) ? t.z[k] : std::numeric_limits<double>::quiet_NaN();
          switch (type)
            {
              case 'I':
                {
                  const std::int16_t v =
                    is_valid(k) ? static_cast<std::int16_t>(std::lround((z - offset) / increment)) :
                                  0;
                  std::memcpy(p, &v, 2);
                  break;
                }
              case 'L':
                {
                  const std::int32_t v =
                    is_valid(k) ? static_cast<std::int32_t>(std::lround((z - offset) / increment)) :
                                  0;
                  std::memcpy(p, &v, 4);
                  break;
                }
              case 'F':
                {
                  const float v = static_cast<float>(z);
                  std::memcpy(p, &v, 4);
                  break;
                }
              default:
                std::memcpy(p, &z, 8);
            }
        }

      std::ostringstream xml;
      xml.precision(17);
      xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          << "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n"
          << " <Record1>\n  <Revision>ISO5436 - 2000</Revision>\n"
          << "  <FeatureType>SUR</FeatureType>\n  <Axes>\n"
          << "   <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>" << t.dx
          << "</Increment><Offset>0</Offset></CX>\n"
          << "   <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>" << t.dy
          << "</Increment><Offset>0</Offset></CY>\n"
          << "   <CZ><AxisType>A</AxisType><DataType>" << type << "</DataType><Increment>"
          << increment << "</Increment><Offset>" << offset << "</Offset></CZ>\n"
          << "  </Axes>\n </Record1>\n"
          << " <Record2><Date>2026-01-01T00:00:00</Date><Creator>GreenTread</Creator></Record2>\n"
          << " <Record3>\n  <MatrixDimension><SizeX>" << t.nx << "</SizeX><SizeY>" << t.ny
          << "</SizeY><SizeZ>1</SizeZ></MatrixDimension>\n"
          << "  <DataLink><PointDataLink>bindata/data.bin</PointDataLink>"
          << "<MD5ChecksumPointData>" << md5(data) << "</MD5ChecksumPointData>"
          << "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
          << "<MD5ChecksumValidPoints>" << md5(bits) << "</MD5ChecksumValidPoints></DataLink>\n"
          << " </Record3>\n <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>\n"
          << "</p:ISO5436_2>\n";
      const std::string main_xml = xml.str();

      base::AtomicFile out(file, std::ios::binary);
      zipFile          zip = zipOpen64(out.temporary_path().c_str(), APPEND_STATUS_CREATE);
      if (!zip)
        throw InputError("X3P file '" + file + "' cannot be written");
      const auto add = [&](const std::string &name, const std::string &bytes) {
        zip_fileinfo info{};
        if (zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                                  Z_DEFLATED, 6, 0) != ZIP_OK ||
            zipWriteInFileInZip(zip, bytes.data(), bytes.size()) != ZIP_OK ||
            zipCloseFileInZip(zip) != ZIP_OK)
          {
            zipClose(zip, nullptr);
            throw InputError("X3P file '" + file + "': member " + name + " cannot be written");
          }
      };
      add("main.xml", main_xml);
      add("md5checksum.hex", md5(main_xml) + " *main.xml\n");
      add("bindata/data.bin", data);
      add("bindata/valid.bin", bits);
      if (zipClose(zip, nullptr) != ZIP_OK)
        throw InputError("X3P file '" + file + "' cannot be written");
      out.commit();
    }
  } // namespace road
} // namespace greentread
