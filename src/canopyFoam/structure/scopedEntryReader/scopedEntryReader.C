// scopedEntryReader.C: the typed, range-checked reads of scopedEntryReader and their error messages.
/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | canopyFoam: parachute fluid-structure interaction
   \\    /   O peration     | for OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of canopyFoam, a plugin for OpenFOAM, and like OpenFOAM
    is distributed under the GNU General Public License version 3 or later.

\*---------------------------------------------------------------------------*/

#include "scopedEntryReader.H"
#include "OStringStream.H"
#include "canopyFoamCompat.H"
#include "Switch.H"

#include <cmath>
#include <cstdio>
#include <cstdlib>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// A token as OpenFOAM describes it (word 'abc', label 3, ...)
std::string describe(const Foam::token& tok)
{
    Foam::OStringStream os;
    os << tok.info();
    return os.str();
}


// The words of a list separated by spaces
std::string spaced(const Foam::wordList& words)
{
    std::string list;
    for (const Foam::word& w : words)
    {
        list += (list.empty() ? "" : " ") + w;
    }
    return list;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scopedEntryReader::scopedEntryReader
(
    const dictionary& dict,
    const std::string& scope
)
:
    dict_(dict),
    scope_(scope)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

const Foam::entry* Foam::scopedEntryReader::find(const word& key) const
{
    return canopyCompat::findLiteral(dict_, key);
}


Foam::ITstream& Foam::scopedEntryReader::stream
(
    const word& key,
    const std::string& what
) const
{
    const entry* e = find(key);
    if (!e)
    {
        fail(key, "is missing (required: " + what + ")");
    }
    if (e->isDict())
    {
        fail(key, "must be a value (" + what + "), not a sub-dictionary");
    }
    return e->stream();
}


const Foam::token& Foam::scopedEntryReader::single
(
    const word& key,
    const std::string& what
) const
{
    ITstream& is = stream(key, what);
    if (is.size() != 1)
    {
        fail
        (
            key,
            "must be a single value (" + what + "), found "
          + std::to_string(is.size()) + " tokens: " + canopyCompat::joinTokens(is)
        );
    }
    return is[0];
}


Foam::scalar Foam::scopedEntryReader::finite
(
    const word& key,
    const std::string& what
) const
{
    const token& tok = single(key, what);
    if (!tok.isNumber())
    {
        fail(key, "must be a number (" + what + "), found " + describe(tok));
    }
    const scalar x = tok.number();
    if (!std::isfinite(x))
    {
        fail(key, "= " + format(x) + " must be finite (" + what + ")");
    }
    return x;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::string Foam::scopedEntryReader::name(const word& key) const
{
    return scope_.empty() ? std::string(key) : scope_ + '.' + key;
}


bool Foam::scopedEntryReader::found(const word& key) const
{
    return find(key) != nullptr;
}


std::string Foam::scopedEntryReader::format(const scalar x)
{
    // 15 digits whatever precision the run's streams have been set to
    // (writePrecision): 0.05, not 0.050000000000000003
    char text[32];
    std::snprintf(text, sizeof(text), "%.15g", x);
    return text;
}


std::string Foam::scopedEntryReader::given(const word& key) const
{
    const entry* e = find(key);
    if (!e)
    {
        return "(missing)";
    }
    if (e->isDict())
    {
        return "{ ... }";
    }
    const ITstream& is = e->stream();
    if (is.size() == 1 && is[0].isNumber())
    {
        return format(is[0].number());
    }
    return is.empty() ? std::string("(empty)") : canopyCompat::joinTokens(is);
}


bool Foam::scopedEntryReader::switchValue(const token& tok, bool& value)
{
    if (canopyCompat::boolToken(tok, value))
    {
        return true;
    }
    if (tok.isWord())
    {
        const Switch sw(tok.wordToken(), true);
        if (sw.valid())
        {
            value = bool(sw);
            return true;
        }
    }
    return false;
}


void Foam::scopedEntryReader::fail
(
    const word& key,
    const std::string& what
) const
{
    FatalIOErrorInFunction(dict_)
        << "Entry '" << name(key).c_str() << "' " << what.c_str() << nl
        << exit(FatalIOError);
    std::abort();   // not reached: FatalIOError exits or throws
}


void Foam::scopedEntryReader::warnUnused
(
    const wordList& used,
    const std::string& context
) const
{
    for (const word& key : dict_.toc())
    {
        if (!canopyCompat::contains(used, key))
        {
            IOWarningInFunction(dict_)
                << "Entry '" << name(key).c_str() << "' is not used"
                << context.c_str() << " and is ignored. Valid entries here: "
                << "(" << spaced(used).c_str() << ")" << endl;
        }
    }
}


void Foam::scopedEntryReader::rejectUnknown(const wordList& valid) const
{
    for (const word& key : dict_.toc())
    {
        if (!canopyCompat::contains(valid, key))
        {
            fail
            (
                key,
                "is not a valid entry here. Valid entries: " + spaced(valid)
            );
        }
    }
}


void Foam::scopedEntryReader::rejectMoved
(
    const word& key,
    const std::string& newName,
    const std::string& example
) const
{
    if (found(key))
    {
        fail(key, "is now " + newName + ": write " + example);
    }
}


void Foam::scopedEntryReader::rejectMovedInto
(
    std::initializer_list<movedEntry> moved
) const
{
    for (const movedEntry& m : moved)
    {
        if (found(m.key) && !dict().isDict(m.key))
        {
            rejectMoved
            (
                m.key,
                name(m.section) + '.' + m.newKey,
                std::string(m.section) + " { " + m.with + m.newKey + ' '
              + given(m.key) + "; }"
            );
        }
    }
}


Foam::scalar Foam::scopedEntryReader::number
(
    const word& key,
    const std::string& what
) const
{
    return finite(key, what);
}


Foam::scalar Foam::scopedEntryReader::number
(
    const word& key,
    const std::string& what,
    const scalar deflt
) const
{
    return found(key) ? finite(key, what) : deflt;
}


Foam::scalar Foam::scopedEntryReader::positive
(
    const word& key,
    const std::string& what
) const
{
    const scalar x = finite(key, what);
    if (!(x > 0))
    {
        fail(key, "= " + format(x) + " must be > 0 (" + what + ")");
    }
    return x;
}


Foam::scalar Foam::scopedEntryReader::positive
(
    const word& key,
    const std::string& what,
    const scalar deflt
) const
{
    return found(key) ? positive(key, what) : deflt;
}


Foam::scalar Foam::scopedEntryReader::nonNegative
(
    const word& key,
    const std::string& what
) const
{
    const scalar x = finite(key, what);
    if (x < 0)
    {
        fail(key, "= " + format(x) + " must be >= 0 (" + what + ")");
    }
    return x;
}


Foam::scalar Foam::scopedEntryReader::nonNegative
(
    const word& key,
    const std::string& what,
    const scalar deflt
) const
{
    return found(key) ? nonNegative(key, what) : deflt;
}


Foam::scalar Foam::scopedEntryReader::inRange
(
    const word& key,
    const std::string& what,
    const scalar lo,
    const scalar hi,
    const scalar deflt
) const
{
    if (!found(key))
    {
        return deflt;
    }
    const scalar x = finite(key, what);
    if (x < lo || x > hi)
    {
        fail
        (
            key,
            "= " + format(x) + " must be in [" + format(lo) + ", " + format(hi)
          + "] (" + what + ")"
        );
    }
    return x;
}


Foam::label Foam::scopedEntryReader::integer
(
    const word& key,
    const std::string& what
) const
{
    const token& tok = single(key, what);
    if (!tok.isLabel())
    {
        fail
        (
            key,
            "must be an integer (" + what + "), found " + describe(tok)
        );
    }
    return tok.labelToken();
}


Foam::label Foam::scopedEntryReader::integer
(
    const word& key,
    const std::string& what,
    const label deflt
) const
{
    return found(key) ? integer(key, what) : deflt;
}


Foam::label Foam::scopedEntryReader::integerAtLeast
(
    const word& key,
    const std::string& what,
    const label lo
) const
{
    const label n = integer(key, what);
    if (n < lo)
    {
        fail
        (
            key,
            "= " + std::to_string(n) + " must be >= " + std::to_string(lo)
          + " (" + what + ")"
        );
    }
    return n;
}


Foam::label Foam::scopedEntryReader::integerAtLeast
(
    const word& key,
    const std::string& what,
    const label lo,
    const label deflt
) const
{
    return found(key) ? integerAtLeast(key, what, lo) : deflt;
}


bool Foam::scopedEntryReader::flag(const word& key, const bool deflt) const
{
    if (!found(key))
    {
        return deflt;
    }
    const token& tok = single(key, "true or false");
    bool value = deflt;
    if (!switchValue(tok, value))
    {
        fail
        (
            key,
            "must be a switch (true/false, on/off, yes/no), found "
          + describe(tok)
        );
    }
    return value;
}


Foam::vector Foam::scopedEntryReader::vectorValue
(
    const word& key,
    const std::string& what
) const
{
    ITstream& is = stream(key, what + ", a vector (x y z)");
    const bool ok =
        is.size() == 5
     && is[0].isPunctuation() && is[0].pToken() == token::BEGIN_LIST
     && is[1].isNumber() && is[2].isNumber() && is[3].isNumber()
     && is[4].isPunctuation() && is[4].pToken() == token::END_LIST;
    if (!ok)
    {
        fail
        (
            key,
            "must be a vector (x y z) (" + what + "), found " + canopyCompat::joinTokens(is)
        );
    }
    const vector v(is[1].number(), is[2].number(), is[3].number());
    if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z()))
    {
        fail(key, "must be finite (" + what + ")");
    }
    return v;
}


Foam::vector Foam::scopedEntryReader::vectorValue
(
    const word& key,
    const std::string& what,
    const vector& deflt
) const
{
    return found(key) ? vectorValue(key, what) : deflt;
}


Foam::vector Foam::scopedEntryReader::nonZeroVector
(
    const word& key,
    const std::string& what
) const
{
    const vector v = vectorValue(key, what);
    if (!(mag(v) > 0))
    {
        fail(key, "= (0 0 0) must not be zero (" + what + ")");
    }
    return v;
}


Foam::vector Foam::scopedEntryReader::nonZeroVector
(
    const word& key,
    const std::string& what,
    const vector& deflt
) const
{
    return found(key) ? nonZeroVector(key, what) : deflt;
}


Foam::word Foam::scopedEntryReader::wordValue
(
    const word& key,
    const std::string& what,
    const word& deflt
) const
{
    if (!found(key))
    {
        return deflt;
    }
    const token& tok = single(key, what);
    if (!tok.isWord())
    {
        fail(key, "must be a word (" + what + "), found " + describe(tok));
    }
    return tok.wordToken();
}


Foam::word Foam::scopedEntryReader::choice
(
    const word& key,
    const wordList& valid,
    const std::string& what
) const
{
    const std::string list(spaced(valid));
    const token& tok = single(key, "the " + what + ", one of: " + list);
    if (!tok.isWord())
    {
        fail
        (
            key,
            "must be a " + what + " name, found " + describe(tok)
          + ". Valid " + what + "s: " + list
        );
    }
    const word& w = tok.wordToken();
    if (!canopyCompat::contains(valid, w))
    {
        fail
        (
            key,
            "= " + w + " is not a known " + what + ". Valid " + what + "s: "
          + list
        );
    }
    return w;
}


Foam::word Foam::scopedEntryReader::choice
(
    const word& key,
    const wordList& valid,
    const std::string& what,
    const word& deflt
) const
{
    return found(key) ? choice(key, valid, what) : deflt;
}


Foam::fileName Foam::scopedEntryReader::fileNameWithExt
(
    const word& key,
    const std::string& what,
    const word& ext
) const
{
    const token& tok = single(key, what);
    if (!tok.isWord() && !tok.isString())
    {
        fail(key, "must be a file name (" + what + "), found " + describe(tok));
    }
    fileName file(tok.isWord() ? tok.wordToken() : tok.stringToken());
    file.expand();
    if (file.ext() != ext)
    {
        fail
        (
            key,
            "= " + file + " must name a file ending in ." + ext + " (" + what
          + ")"
        );
    }
    return file;
}


const Foam::dictionary* Foam::scopedEntryReader::optionalDict
(
    const word& key
) const
{
    const entry* e = find(key);
    if (!e)
    {
        return nullptr;
    }
    if (!e->isDict())
    {
        fail(key, "must be a sub-dictionary { ... }");
    }
    return &e->dict();
}


const Foam::dictionary& Foam::scopedEntryReader::requiredDict
(
    const word& key,
    const std::string& what
) const
{
    const dictionary* d = optionalDict(key);
    if (!d)
    {
        fail(key, "is missing: a sub-dictionary " + what + " is required");
    }
    return *d;
}


Foam::scopedEntryReader Foam::scopedEntryReader::subReader
(
    const word& key,
    const std::string& what
) const
{
    return scopedEntryReader(requiredDict(key, what), name(key));
}


Foam::scopedEntryReader Foam::scopedEntryReader::optionalSubReader
(
    const word& key
) const
{
    const dictionary* d = optionalDict(key);
    return scopedEntryReader(d ? *d : dictionary::null, name(key));
}


// ************************************************************************* //
