// SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
    foamSha1Probe: does this OpenFOAM's Foam::dictionary::digest() work?
    Exit status 0 and the digest of a one-entry dictionary on stdout if so;
    OpenFOAM's FatalIOError (exit status 1) if not: v1912 built with GCC 12
    or later (../dictionaryDigest.C says why). ./Allwmake runs it with and
    without libroughContactSha1Fix preloaded.
\*---------------------------------------------------------------------------*/

#include "dictionary.H"
#include "IOstreams.H"
#include "SHA1Digest.H"

int main()
{
    Foam::dictionary dict;
    dict.add("probe", Foam::word("sha1"));
    dict.add("value", 1);
    Foam::Info<< dict.digest() << Foam::endl;
    return 0;
}
