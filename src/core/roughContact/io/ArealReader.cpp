// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface from a file of either format.
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/NpyReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/MatrixReader.hpp"
#include "roughContact/io/X3pReader.hpp"

#include <cctype>

namespace roughContact {

bool isX3pPath(const std::string& path)
{
    const std::string ext = ".x3p";
    if (path.size() < ext.size()) {
        return false;
    }
    for (std::size_t i = 0; i < ext.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i]) {
            return false;
        }
    }
    return true;
}

ArealSurface readAreal(const std::string& path, const ArealReadOptions& options)
{
    if (isX3pPath(path)) {
        const char* const own =
            "an X3P file carries its own spacings, in metres (Record1/Axes); this option is "
            "for a text matrix of heights";
        if (options.dx) {
            throw ParameterError("dx", own);
        }
        if (options.dy) {
            throw ParameterError("dy", own);
        }
        if (options.units) {
            throw ParameterError("units", own);
        }
        X3pReadOptions x3p;
        x3p.fillInvalid = options.fillInvalid;
        return readX3p(path, x3p);
    }
    if (options.fillInvalid) {
        throw ParameterError("fillInvalid", "is for X3P files (invalid points); a text matrix or a .npy array "
                                            "has none: a NaN in it is an error");
    }
    MatrixReadOptions matrix;
    matrix.units = options.units.value_or(LengthUnit::m);
    matrix.dx = options.dx;
    matrix.dy = options.dy;
    return isNpyPath(path) ? readNpy(path, matrix) : readMatrix(path, matrix);
}

} // namespace roughContact
