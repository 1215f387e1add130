#pragma once

#include <hdf5.h>

#include <complex>
#include <string>
#include <vector>

/**
 * @file
 * A stage's HDF5 file written without the times HDF5 stamps on every object
 * by default, so that the same stage writes the same bytes. The layout is
 * deal.II's (dealii::HDF5, which reads the files back): contiguous datasets
 * of double, int or std::complex<double> (a compound of "r" and "i"), and
 * variable-length UTF-8 string attributes on the root group.
 */

namespace greentread
{
  namespace base
  {
    class Hdf5Writer
    {
    public:
      /// One dataset being written: Hdf5Writer::create_dataset().
      template <typename T>
      struct Dataset
      {
        Hdf5Writer          &file;
        std::string          name;
        std::vector<hsize_t> dimensions;

        /// Write @p values, as many as the dimensions hold, row-major.
        void
        write(const std::vector<T> &values) const
        {
          file.write_dataset(name, dimensions, values.data(), values.size(), type_of<T>());
        }
      };

      /// Create (truncate) @p file.
      explicit Hdf5Writer(const std::string &file);
      ~Hdf5Writer();
      Hdf5Writer(const Hdf5Writer &) = delete;
      Hdf5Writer &
      operator=(const Hdf5Writer &) = delete;

      /// The dataset @p name of @p dimensions, written by its write().
      template <typename T>
      Dataset<T>
      create_dataset(const std::string &name, const std::vector<hsize_t> &dimensions)
      {
        return {*this, name, dimensions};
      }

      /// A string attribute of the root group.
      void
      set_attribute(const std::string &name, const std::string &value);

    private:
      enum class Type
      {
        real,
        integer,
        complex
      };

      template <typename T>
      static Type
      type_of();

      void
      write_dataset(const std::string          &name,
                    const std::vector<hsize_t> &dimensions,
                    const void                 *values,
                    std::size_t                 count,
                    Type                        type);

      std::string file_name;
      hid_t       file = -1;
    };

    template <>
    inline Hdf5Writer::Type
    Hdf5Writer::type_of<double>()
    {
      return Type::real;
    }

    template <>
    inline Hdf5Writer::Type
    Hdf5Writer::type_of<int>()
    {
      return Type::integer;
    }

    template <>
    inline Hdf5Writer::Type
    Hdf5Writer::type_of<std::complex<double>>()
    {
      return Type::complex;
    }
  } // namespace base
} // namespace greentread
