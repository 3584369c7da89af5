// Strict scalar parsing shared by the catalog readers: a whole field must be one number
// (no trailing text, no hex, no inf/nan), Alpha-5 catalog numbers, ISO 8601 UTC epochs.
#pragma once

#include <string>

namespace evade::sgp4 {

/// Trims spaces, tabs, CR and LF at both ends.
std::string trim(const std::string& s);

/// Value of a field of decimal digits only, as the readers' fixed-width fields are once
/// checked (callers check; at most 18 digits, so no overflow). "" is 0.
long digits_value(const std::string& digits);

/// A decimal number, optionally signed, with optional fraction and exponent ("-.00000084",
/// "1.5E-4", "42"), surrounded by blanks only. False for anything else.
bool parse_plain_decimal(const std::string& field, double& out);

/// A catalog title (an object's name) as UTF-8 in *out: valid UTF-8 is kept as it is; any other
/// text is read as Latin-1 (ISO 8859-1: each byte the code point of its value, as older catalog
/// exports write names) and written as UTF-8. Returns 0, or the 1-based byte column of the first
/// control character (U+0000-U+001F, U+007F-U+009F), which no title may hold (*out is then "",
/// and *control, if given, that character's code point).
int title_to_utf8(const std::string& raw, std::string* out, long* control = nullptr);

/// title_to_utf8 for a whole text (a CDM, an OMM file): the same decoding, the control
/// characters in `allowed` (e.g. "\t\r\n") let through. Returns 0 or the 1-based byte offset.
int text_to_utf8(const std::string& raw, std::string* out, long* control, const char* allowed);

/// "U+0007": a code point as error messages name it.
std::string code_point_name(long cp);

/// raw as text for a message (a file name, an expected or found field): decoded as
/// title_to_utf8 decodes it, each control character written as "<U+XXXX>". Always valid UTF-8.
std::string printable_utf8(const std::string& raw);

/// An integer (optionally signed) surrounded by blanks only.
bool parse_plain_integer(const std::string& field, long& out);

/// A 5-character NORAD catalog number: digits (leading blanks allowed) or Alpha-5
/// (A..Z without I and O standing for 10..33, then 4 digits: "A0001" = 100001).
bool parse_alpha5(const std::string& field, long& out);

/// "YYYY-MM-DDThh:mm:ss[.f...]" or "YYYY-DDDThh:mm:ss[.f...]" (day of year), optional
/// trailing 'Z', years 1957..2099. Gives the year and the day of year (1.0 = Jan 1 00:00).
bool parse_iso_epoch(const std::string& text, int& year, double& day_of_year);

}  // namespace evade::sgp4
