// SPDX-License-Identifier: GPL-3.0-or-later
// Where the entries of a contact specification come from. Each front-end has one source: the
// OpenFOAM dictionary (entries, sub-dictionaries, their lines), the command line (options),
// Python (keyword arguments). A source only turns its own syntax into values and says how the
// user wrote an entry; every rule about the entries (names, defaults, which entries go with
// which surface type or model, ranges) is the reader's (InterfaceSpecReader.hpp), written once.
//
// SpecValues is a source held in memory: the CLI and Python fill one from their options and
// arguments, the tests one per rule.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace roughContact {

class SpecSource {
public:
    virtual ~SpecSource() = default;

    /// The entries given, in the order given (for the rule that every entry is known).
    virtual std::vector<std::string> keys() const = 0;
    virtual bool has(const std::string& key) const = 0;
    /// True when the entry is a sub-specification (`gas { ... }` rather than `gas air;`).
    virtual bool isSub(const std::string& key) const = 0;
    /// True when the entry is a word rather than a number (`Sy none;` rather than `Sy 4e8;`).
    virtual bool isWord(const std::string& key) const = 0;

    /// The entry as a word (a name: model, type, units). Each getter throws ParameterError naming
    /// the entry (name()) when it is missing or of another kind.
    virtual std::string word(const std::string& key) const = 0;
    /// The entry as a file path, as it is to be opened (a dictionary's relative to the case).
    virtual std::string path(const std::string& key) const = 0;
    /// The entry as a number (not checked: the reader checks its range).
    virtual double number(const std::string& key) const = 0;
    /// The entry as a list of numbers.
    virtual std::vector<double> numbers(const std::string& key) const = 0;
    /// The entry as a whole number >= 0.
    virtual std::uint64_t whole(const std::string& key) const = 0;
    /// The entry as a switch (yes/no, true/false, on/off).
    virtual bool flag(const std::string& key) const = 0;
    /// The entry as one sub-specification, or as a list of them.
    virtual std::unique_ptr<SpecSource> sub(const std::string& key) const = 0;
    virtual std::vector<std::unique_ptr<SpecSource>> subs(const std::string& key) const = 0;

    /// How the user wrote the entry, for an error message: "entry 'stride' of surface (line 23)",
    /// "--stride", "stride".
    virtual std::string name(const std::string& key) const = 0;
    /// What this source is, for messages about it as a whole: "side1", "solid 1", "surface".
    virtual std::string context() const = 0;
    /// Where the entry is written, for an error about its value that names the property rather
    /// than the entry ("side2 yield strength S_y"): a dictionary's "entry 'Sy' of side2 (line
    /// 20)"; "" where the property's name is what the user wrote (options, arguments).
    virtual std::string locate(const std::string& /*key*/) const { return ""; }
};

/// A source held in memory: values set by a front-end or a test.
class SpecValues final : public SpecSource {
public:
    using Value = std::variant<bool, double, std::uint64_t, std::string, std::vector<double>,
                               std::shared_ptr<const SpecValues>, std::vector<std::shared_ptr<const SpecValues>>>;
    /// naming: how a key is written in this front-end ("--" + key, or key); unset: 'key' of context.
    explicit SpecValues(std::string context, std::function<std::string(const std::string&)> naming = {});

    /// Sets an entry (replacing one of the same key); `as`: how it is named in errors, if not
    /// by the naming function (the CLI's --dx for a profile's spacing).
    SpecValues& set(const std::string& key, Value value, const std::string& as = "");

    std::vector<std::string> keys() const override;
    bool has(const std::string& key) const override;
    bool isSub(const std::string& key) const override;
    bool isWord(const std::string& key) const override;
    std::string word(const std::string& key) const override;
    std::string path(const std::string& key) const override { return word(key); }
    double number(const std::string& key) const override;
    std::vector<double> numbers(const std::string& key) const override;
    std::uint64_t whole(const std::string& key) const override;
    bool flag(const std::string& key) const override;
    std::unique_ptr<SpecSource> sub(const std::string& key) const override;
    std::vector<std::unique_ptr<SpecSource>> subs(const std::string& key) const override;
    std::string name(const std::string& key) const override;
    std::string context() const override { return context_; }

private:
    struct Entry {
        std::string key;
        Value value;
        std::string as;
    };
    std::string context_;
    std::function<std::string(const std::string&)> naming_;
    std::vector<Entry> entries_;

    const Entry& find(const std::string& key) const;
    [[noreturn]] void wrongKind(const std::string& key, const char* expected) const;
};

} // namespace roughContact
