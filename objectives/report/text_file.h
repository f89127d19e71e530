#pragma once
// WriteTextFile: every output table, picture and result file is written through this one
// function, so a failed write (missing directory, full disk) is reported alike everywhere.
//
//   WriteTextFile(dir + "/runs.csv", [&](std::ostream& out) { out << "a,b\n"; }, &error);
#include <functional>
#include <ostream>
#include <string>

namespace demcal::objectives {

// Truncates `path`, lets `write` fill it and flushes; false with "cannot write '<path>'" in
// *error (if given) when the file could not be opened or written.
bool WriteTextFile(const std::string& path, const std::function<void(std::ostream&)>& write,
                   std::string* error);

}  // namespace demcal::objectives
