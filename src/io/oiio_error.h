// Internal: OpenImageIO error text squeezed onto one line, for InputError messages.
#pragma once
#include <string>

#include <OpenImageIO/imageio.h>

namespace fastshade::io {

// OIIO messages may span lines and may repeat the file name; keep them on one line.
inline std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// The global OIIO error (set by failed create()/open()), consumed so that it is neither
// reported against a later call nor printed as "pending" when the program exits.
inline std::string take_global_error() { return one_line(OIIO::geterror()); }

}  // namespace fastshade::io
