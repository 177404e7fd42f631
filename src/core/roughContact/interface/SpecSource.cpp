// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/SpecSource.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Numbers.hpp"

#include <algorithm>
#include <cmath>

namespace roughContact {

SpecValues::SpecValues(std::string context, std::function<std::string(const std::string&)> naming)
    : context_(std::move(context)), naming_(std::move(naming))
{
}

SpecValues& SpecValues::set(const std::string& key, Value value, const std::string& as)
{
    for (Entry& e : entries_) {
        if (e.key == key) {
            e.value = std::move(value);
            e.as = as;
            return *this;
        }
    }
    entries_.push_back({key, std::move(value), as});
    return *this;
}

std::vector<std::string> SpecValues::keys() const
{
    std::vector<std::string> out;
    for (const Entry& e : entries_) {
        out.push_back(e.key);
    }
    return out;
}

bool SpecValues::has(const std::string& key) const
{
    return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
}

const SpecValues::Entry& SpecValues::find(const std::string& key) const
{
    for (const Entry& e : entries_) {
        if (e.key == key) {
            return e;
        }
    }
    throw ParameterError(name(key), "is missing");
}

void SpecValues::wrongKind(const std::string& key, const char* expected) const
{
    throw ParameterError(name(key), std::string("expects ") + expected);
}

bool SpecValues::isSub(const std::string& key) const
{
    return has(key) && std::holds_alternative<std::shared_ptr<const SpecValues>>(find(key).value);
}

bool SpecValues::isWord(const std::string& key) const
{
    if (!has(key)) {
        return false;
    }
    const Value& v = find(key).value;
    double ignored = 0.0;
    return std::holds_alternative<std::string>(v) && !parseNumber(std::get<std::string>(v), ignored);
}

std::string SpecValues::word(const std::string& key) const
{
    const Value& v = find(key).value;
    if (!std::holds_alternative<std::string>(v)) {
        wrongKind(key, "a word");
    }
    return std::get<std::string>(v);
}

double SpecValues::number(const std::string& key) const
{
    const Value& v = find(key).value;
    if (const auto* d = std::get_if<double>(&v)) {
        return *d;
    }
    if (const auto* n = std::get_if<std::uint64_t>(&v)) {
        return static_cast<double>(*n);
    }
    if (const auto* s = std::get_if<std::string>(&v)) {
        double d = 0.0;
        if (parseNumber(*s, d)) {
            return d;
        }
        throw ParameterError(name(key), "expects a number, got '" + *s + "'");
    }
    wrongKind(key, "a number");
}

std::vector<double> SpecValues::numbers(const std::string& key) const
{
    const Value& v = find(key).value;
    if (const auto* list = std::get_if<std::vector<double>>(&v)) {
        return *list;
    }
    return {number(key)};
}

std::uint64_t SpecValues::whole(const std::string& key) const
{
    const Value& v = find(key).value;
    if (const auto* n = std::get_if<std::uint64_t>(&v)) {
        return *n;
    }
    if (const auto* s = std::get_if<std::string>(&v)) {
        return parseWholeNumber(*s, name(key), "the value");
    }
    const double d = number(key);
    // Exact in a double up to 2^53; beyond, a whole number is given as text or uint64.
    if (!(std::isfinite(d) && d >= 0.0 && d <= 9007199254740992.0 && d == std::floor(d))) {
        throw ParameterError(name(key), "expects a whole number >= 0, got " + formatNumber(d, 17));
    }
    return static_cast<std::uint64_t>(d);
}

bool SpecValues::flag(const std::string& key) const
{
    const Value& v = find(key).value;
    if (const auto* b = std::get_if<bool>(&v)) {
        return *b;
    }
    if (const auto* s = std::get_if<std::string>(&v)) {
        for (const char* yes : {"yes", "true", "on"}) {
            if (*s == yes) {
                return true;
            }
        }
        for (const char* no : {"no", "false", "off"}) {
            if (*s == no) {
                return false;
            }
        }
    }
    wrongKind(key, "yes or no");
}

std::unique_ptr<SpecSource> SpecValues::sub(const std::string& key) const
{
    const Value& v = find(key).value;
    if (const auto* s = std::get_if<std::shared_ptr<const SpecValues>>(&v)) {
        return std::make_unique<SpecValues>(**s);
    }
    wrongKind(key, "a sub-specification");
}

std::vector<std::unique_ptr<SpecSource>> SpecValues::subs(const std::string& key) const
{
    const Value& v = find(key).value;
    std::vector<std::unique_ptr<SpecSource>> out;
    if (const auto* list = std::get_if<std::vector<std::shared_ptr<const SpecValues>>>(&v)) {
        for (const auto& s : *list) {
            out.push_back(std::make_unique<SpecValues>(*s));
        }
        return out;
    }
    out.push_back(sub(key));
    return out;
}

std::string SpecValues::name(const std::string& key) const
{
    for (const Entry& e : entries_) {
        if (e.key == key && !e.as.empty()) {
            return e.as;
        }
    }
    if (naming_) {
        return naming_(key);
    }
    return "'" + key + "' of " + context_;
}

} // namespace roughContact
