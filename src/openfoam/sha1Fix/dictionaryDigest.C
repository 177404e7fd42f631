// SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
    libroughContactSha1Fix: Foam::dictionary::digest() for an OpenFOAM v1912
    built with GCC 12 or later (Debian 13's openfoam 1912.200626-3+b1), where
    it fails with "error in IOstream "sha1" for operation
    Foam::Ostream& Foam::operator<<(Ostream&, const word&)": v1912's
    osha1stream gives its std::streambuf only xsputn(), and the libstdc++ of
    GCC 12 and later writes single characters through overflow(), whose
    default returns EOF and sets badbit. Every case with function objects
    dies at the start (functionObjectList digests each function's
    dictionary), with or without this project's condition. OpenFOAM fixed its
    own stream in later releases by adding the missing overflow().

    This file is the same digest (v1912's dictionary::digest: every entry
    written to a SHA1 stream) through a stream buffer that has both.
    ./Allwmake (etc/openfoam/sha1Fix) builds it only where probe/ finds the digest
    broken, and then puts wrappers for the OpenFOAM applications first on
    the PATH (build/openfoam/bin, by etc/openfoam/environment) that preload it:
    the dynamic linker then binds libOpenFOAM's calls of
    Foam::dictionary::digest() to this one. Derived from OpenFOAM v1912's
    src/OpenFOAM/db/dictionary/dictionary.C (GPL-3.0-or-later, OpenCFD Ltd.).
\*---------------------------------------------------------------------------*/

#include "dictionary.H"
#include "primitiveEntry.H"
#include "OSstream.H"
#include "SHA1.H"

#include <ostream>
#include <streambuf>

namespace
{

//- A stream buffer that feeds everything written to it into a SHA1
class sha1Buffer
:
    public std::streambuf
{
    Foam::SHA1 sha1_;

protected:

    std::streamsize xsputn(const char* s, std::streamsize n) override
    {
        sha1_.append(s, n);
        return n;
    }

    int_type overflow(int_type c) override
    {
        if (!traits_type::eq_int_type(c, traits_type::eof()))
        {
            const char ch = traits_type::to_char_type(c);
            sha1_.append(&ch, 1);
        }
        return traits_type::not_eof(c);
    }

public:

    Foam::SHA1Digest digest()
    {
        return sha1_.digest();
    }
};

} // End anonymous namespace


Foam::SHA1Digest Foam::dictionary::digest() const
{
    sha1Buffer buf;
    std::ostream stream(&buf);
    OSstream os(stream, "sha1");

    // Process entries
    for (const entry& e : *this)
    {
        os << e;
    }

    return buf.digest();
}
