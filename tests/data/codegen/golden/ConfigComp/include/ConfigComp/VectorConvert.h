// -*- C++ -*-
/*
 * VectorConvert.h: reads the std::vector configuration parameters of ConfigComp from text.
 *
 * OpenRTM-aist converts a configuration value with `stream >> variable`, and the standard
 * library has no such extraction for std::vector. This header adds it: the text is split at
 * commas, blanks around each element are dropped, and each element is read as the element
 * type (a std::string element keeps all of its text, inner blanks included). Blank text gives
 * an empty vector. When an element cannot be read, the stream fails and the vector keeps its
 * previous value.
 *
 * Include it before any OpenRTM-aist header, so that the conversion templates of coil see it.
 */

#ifndef VECTORCONVERT_H
#define VECTORCONVERT_H

#include <istream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace VectorConvertDetail
{
  inline std::string trimmed(const std::string& text)
  {
    const char* const blanks = " \t\r\n\v\f";
    const std::string::size_type begin = text.find_first_not_of(blanks);
    if (begin == std::string::npos)
      {
        return std::string();
      }
    const std::string::size_type end = text.find_last_not_of(blanks);
    return text.substr(begin, end - begin + 1);
  }

  // One element: the whole of its text must be a value of the element type.
  template <typename T>
  bool readElement(const std::string& text, T& value)
  {
    std::istringstream in(text);
    in >> value;
    if (in.fail())
      {
        return false;
      }
    in >> std::ws;
    return in.eof();
  }

  inline bool readElement(const std::string& text, std::string& value)
  {
    value = text;
    return true;
  }
} // namespace VectorConvertDetail

template <typename T>
std::istream& operator>>(std::istream& in, std::vector<T>& values)
{
  const std::string text((std::istreambuf_iterator<char>(in)),
                         std::istreambuf_iterator<char>());
  in.setstate(std::ios::eofbit);
  std::vector<T> read;
  if (!VectorConvertDetail::trimmed(text).empty())
    {
      std::string::size_type begin = 0;
      for (;;)
        {
          const std::string::size_type comma = text.find(',', begin);
          const std::string element = VectorConvertDetail::trimmed(
              text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
          T value = T();
          if (!VectorConvertDetail::readElement(element, value))
            {
              in.setstate(std::ios::failbit);
              return in;
            }
          read.push_back(value);
          if (comma == std::string::npos)
            {
              break;
            }
          begin = comma + 1;
        }
    }
  values.swap(read);
  return in;
}

#endif // VECTORCONVERT_H
