#pragma once
// WriteTextFile: every output table, picture and result file is written through this one
// function, so a failed write (missing directory, full disk) is reported alike everywhere.
//
//   WriteTextFile(dir + "/runs.csv", [&](std::ostream& out) { out << "a,b\n"; }, &error);
#include <functional>
#include <ostream>
#include <string>

namespace demcal::objectives {

// Lets `write` fill a temporary beside `path`, fsyncs it and renames it over `path`
// (core/io/atomic_file.h): a kill at any byte leaves the old or the new complete file. False
// with "cannot write '<path>': reason" in *error (if given); `path` is then unchanged.
bool WriteTextFile(const std::string& path, const std::function<void(std::ostream&)>& write,
                   std::string* error);

}  // namespace demcal::objectives
