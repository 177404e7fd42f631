// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). Builds on OpenFOAM (Copyright
// OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later).
#include "dictionarySpecSource.H"
#include "foamCompat.H"

#include "IOstreams.H"
#include "ITstream.H"
#include "PtrList.H"
#include "scalarList.H"

#include "roughContact/Error.hpp"
#include "roughContact/io/Numbers.hpp"

#include <cmath>

namespace Foam
{

dictionarySpecSource::dictionarySpecSource
(
    const dictionary& dict,
    const std::string& context,
    const fileName& casePath
)
:
    dict_(dict),
    context_(context),
    casePath_(casePath)
{}


dictionarySpecSource::dictionarySpecSource
(
    std::shared_ptr<const dictionary> owned,
    const std::string& context,
    const fileName& casePath
)
:
    owned_(std::move(owned)),
    dict_(*owned_),
    context_(context),
    casePath_(casePath)
{}


std::vector<std::string> dictionarySpecSource::keys() const
{
    std::vector<std::string> out;
    for (const Foam::word& k : dict_.toc())
    {
        out.push_back(k);
    }
    return out;
}


bool dictionarySpecSource::has(const std::string& key) const
{
    return dict_.found(key);
}


bool dictionarySpecSource::isSub(const std::string& key) const
{
    return dict_.isDict(key);
}


bool dictionarySpecSource::isWord(const std::string& key) const
{
    if (!dict_.found(key) || dict_.isDict(key))
    {
        return false;
    }
    ITstream& is = dict_.lookup(key);
    return is.size() && is[0].isWord();
}


std::string dictionarySpecSource::word(const std::string& key) const
{
    return foamCompat::get<Foam::word>(dict_, key);
}


std::string dictionarySpecSource::path(const std::string& key) const
{
    fileName f = foamCompat::get<fileName>(dict_, key);
    f.expand();
    if (!f.isAbsolute())
    {
        f = casePath_/f;
    }
    return f;
}


double dictionarySpecSource::number(const std::string& key) const
{
    return foamCompat::get<scalar>(dict_, key);
}


std::vector<double> dictionarySpecSource::numbers(const std::string& key) const
{
    const scalarList v(dict_.lookup(key));
    return std::vector<double>(v.begin(), v.end());
}


std::uint64_t dictionarySpecSource::whole(const std::string& key) const
{
    // A label (int32 or int64 as OpenFOAM is built); a number that is not
    // one (2.5, -3) is named by the core's rule, not OpenFOAM's.
    ITstream& is = dict_.lookup(key);
    if (is.size() == 1 && is[0].isLabel() && is[0].labelToken() >= 0)
    {
        return std::uint64_t(is[0].labelToken());
    }
    if (is.size() == 1 && is[0].isNumber())
    {
        const double d = is[0].number();
        if (d >= 0 && d <= 9007199254740992.0 && d == std::floor(d))
        {
            return std::uint64_t(d);
        }
        throw roughContact::ParameterError
        (
            name(key), "expects a whole number >= 0, got "
          + roughContact::formatNumber(d, 17)
        );
    }
    // Not a number at all: OpenFOAM's own error, naming the entry
    return std::uint64_t(foamCompat::get<label>(dict_, key));
}


bool dictionarySpecSource::flag(const std::string& key) const
{
    return foamCompat::get<bool>(dict_, key);
}


std::unique_ptr<roughContact::SpecSource> dictionarySpecSource::sub
(
    const std::string& key
) const
{
    const std::string context = context_.empty() ? key : context_ + " " + key;
    return std::make_unique<dictionarySpecSource>
    (
        dict_.subDict(key), context, casePath_
    );
}


std::vector<std::unique_ptr<roughContact::SpecSource>>
dictionarySpecSource::subs(const std::string& key) const
{
    std::vector<std::unique_ptr<roughContact::SpecSource>> out;
    if (dict_.isDict(key))
    {
        out.push_back(sub(key));
        return out;
    }
    const PtrList<dictionary> list(dict_.lookup(key));
    forAll(list, i)
    {
        out.push_back
        (
            std::make_unique<dictionarySpecSource>
            (
                std::make_shared<const dictionary>(list[i]),
                key + " " + std::to_string(i + 1) + " (side"
              + std::to_string(i + 1) + ")",
                casePath_
            )
        );
    }
    return out;
}


std::string dictionarySpecSource::name(const std::string& key) const
{
    std::string out = "entry '" + key + "'";
    if (!context_.empty())
    {
        out += " of " + context_;
    }
    const entry* e = foamCompat::findEntry(dict_, key);
    if (e && e->startLineNumber() > 0)
    {
        out += " (line " + std::to_string(e->startLineNumber()) + ")";
    }
    return out;
}

} // End namespace Foam
