#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>
#include <greentread/config.h>

#include <boost/crc.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

namespace greentread
{
  namespace base
  {
    namespace
    {
      void
      put_u32(std::vector<char> &bytes, const std::uint32_t value)
      {
        for (int shift = 24; shift >= 0; shift -= 8)
          bytes.push_back(static_cast<char>((value >> shift) & 0xff));
      }



      /**
       * Insert a PNG tEXt chunk (keyword, Latin-1 text) before IEND.
       * Returns false if the file does not look like a PNG.
       */
      bool
      add_png_text(const std::filesystem::path &file,
                   const std::string           &keyword,
                   const std::string           &text)
      {
        std::ifstream     in(file, std::ios::binary);
        std::vector<char> png((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
        in.close();
        const std::string iend = "IEND";
        if (png.size() < 20 || std::string(png.end() - 8, png.end() - 4) != iend)
          return false;

        std::vector<char> data(keyword.begin(), keyword.end());
        data.push_back('\0');
        data.insert(data.end(), text.begin(), text.end());

        std::vector<char> chunk;
        put_u32(chunk, static_cast<std::uint32_t>(data.size()));
        const std::string type = "tEXt";
        chunk.insert(chunk.end(), type.begin(), type.end());
        chunk.insert(chunk.end(), data.begin(), data.end());
        boost::crc_32_type crc;
        crc.process_bytes(chunk.data() + 4, chunk.size() - 4);
        put_u32(chunk, crc.checksum());

        png.insert(png.end() - 12, chunk.begin(), chunk.end());
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(png.data(), static_cast<std::streamsize>(png.size()));
        return out.good();
      }
    } // namespace



    bool
    gnuplot_available()
    {
      static const bool available =
        std::system((std::string(GREENTREAD_GNUPLOT) + " -e 'exit' > /dev/null 2>&1").c_str()) == 0;
      return available;
    }



    std::string
    gnuplot_quote(const std::filesystem::path &path)
    {
      std::string quoted = "'";
      for (const char c : path.string())
        quoted += (c == '\'') ? std::string("''") : std::string(1, c);
      return quoted + "'";
    }



    bool
    plot_png(const std::filesystem::path &png,
             const std::string           &commands,
             const ParameterRecord       &record,
             const unsigned int           width,
             const unsigned int           height)
    {
      if (!gnuplot_available())
        {
          std::cerr << "warning: gnuplot was not found, so " << png.string()
                    << " was not drawn (apt-get install gnuplot-nox)\n";
          return false;
        }
      AtomicFile image(png, std::ios::binary);
      image.stream().close();

      AtomicFile script(png.string() + ".gp");
      script.stream() << "set terminal pngcairo size " << width << ',' << height << " font ',11'\n"
                      << "set output " << gnuplot_quote(image.temporary_path()) << "\n"
                      << commands << "\nunset output\n";
      script.stream().close();

      const std::string command = std::string(GREENTREAD_GNUPLOT) + " " +
                                  gnuplot_quote(script.temporary_path()) + " > /dev/null 2>&1";
      if (std::system(command.c_str()) != 0 ||
          !add_png_text(image.temporary_path(), "parameters", record.text()))
        {
          std::cerr << "warning: gnuplot failed to draw " << png.string()
                    << "; the data files are complete\n";
          return false;
        }
      image.commit();
      return true;
    }
  } // namespace base
} // namespace greentread
