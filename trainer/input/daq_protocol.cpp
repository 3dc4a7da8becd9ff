#include "trainer/input/daq_protocol.h"

#include <stdexcept>

namespace trainer::daq {

namespace {

constexpr char kHexDigits[] = "0123456789ABCDEF";

// one hex digit, either case; -1 if not one
int hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

// a decimal field of 1…5 digits whose value is in [min, max]
std::optional<unsigned> parseNumber(std::string_view s, unsigned min, unsigned max)
{
    if (s.empty() || s.size() > 5)
        return std::nullopt;
    unsigned v = 0;
    for (char c : s) {
        if (c < '0' || c > '9')
            return std::nullopt;
        v = v * 10 + unsigned(c - '0');
    }
    if (v < min || v > max)
        return std::nullopt;
    return v;
}

// splits at ',' into at most fields.size() pieces; the count, or fields.size() + 1
// when there are more
template <std::size_t N>
std::size_t splitFields(std::string_view s, std::array<std::string_view, N>& fields)
{
    std::size_t n = 0;
    for (;;) {
        const std::size_t comma = s.find(',');
        if (n == N)
            return N + 1;
        fields[n++] = s.substr(0, comma);
        if (comma == std::string_view::npos)
            return n;
        s.remove_prefix(comma + 1);
    }
}

bool validName(std::string_view name)
{
    for (char c : name) {
        if (c < 0x20 || c > 0x7E || c == ',' || c == '*' || c == '$' || c == '#')
            return false;
    }
    return true;
}

}  // namespace

std::uint8_t crc8(std::string_view bytes)
{
    std::uint8_t crc = 0x00;
    for (char c : bytes) {
        crc ^= static_cast<std::uint8_t>(c);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x80) ? static_cast<std::uint8_t>((crc << 1) ^ 0x07) : static_cast<std::uint8_t>(crc << 1);
    }
    return crc;
}

std::string framedLine(char marker, std::string_view body)
{
    const std::uint8_t crc = crc8(body);
    std::string line;
    line.reserve(body.size() + 5);
    line += marker;
    line += body;
    line += '*';
    line += kHexDigits[crc >> 4];
    line += kHexDigits[crc & 0x0F];
    line += '\n';
    return line;
}

std::string sampleLine(std::uint16_t seq, std::span<const std::uint16_t> values)
{
    if (values.empty() || values.size() > std::size_t(kMaxChannels))
        throw std::invalid_argument("daq::sampleLine: 1 to 16 values");
    std::string body = std::to_string(seq);
    for (std::uint16_t v : values) {
        body += ',';
        body += std::to_string(v);
    }
    return framedLine('$', body);
}

std::string identificationLine(const Identification& id)
{
    if (id.version < 0 || id.version > 65535 || id.channels < 1 || id.channels > kMaxChannels || id.bits < 1
        || id.bits > 16 || id.rate < kMinRate || id.rate > kMaxRate || !validName(id.name))
        throw std::invalid_argument("daq::identificationLine: a field is out of range");
    std::string body(kIdentificationTag);
    for (int v : {id.version, id.channels, id.bits, id.rate}) {
        body += ',';
        body += std::to_string(v);
    }
    if (!id.name.empty()) {
        body += ',';
        body += id.name;
    }
    return framedLine('#', body);
}

std::string identificationRequest()
{
    return "?\n";
}

std::string rateCommand(int hz)
{
    if (hz < kMinRate || hz > kMaxRate)
        throw std::invalid_argument("daq::rateCommand: the rate must be 1 to 1000 Hz");
    return "R" + std::to_string(hz) + "\n";
}

Parser::Parser()
{
    m_line.reserve(kMaxLineLength + 2);
}

void Parser::reset()
{
    *this = Parser();
}

void Parser::resetStream()
{
    m_state = State::Idle;
    m_junk = false;
    m_line.clear();
    m_lastSeq.reset();
}

std::size_t Parser::feed(std::string_view bytes)
{
    m_newSamples = 0;
    for (char c : bytes) {
        switch (m_state) {
        case State::Idle:
            if (c == '\n') {
                if (m_junk)
                    ++m_stats.garbageLines;
                m_junk = false;
            } else if (c == '$' || c == '#') {
                if (m_junk)
                    ++m_stats.garbageLines;
                m_junk = false;
                m_line.assign(1, c);
                m_state = State::InLine;
            } else if (c != '\r') {
                m_junk = true;
            }
            break;
        case State::InLine:
            if (c == '\n') {
                endLine();
                m_line.clear();
                m_state = State::Idle;
            } else if (c == '$' || c == '#') {
                // a new line began before this one ended (device reset, lost "\n")
                ++m_stats.badSyntax;
                m_line.assign(1, c);
            } else if (m_line.size() > kMaxLineLength) {
                // room for kMaxLineLength bytes and a "\r" is used up: skip to "\n"
                ++m_stats.tooLong;
                m_line.clear();
                m_state = State::Skipping;
            } else {
                m_line.push_back(c);
            }
            break;
        case State::Skipping:
            if (c == '\n')
                m_state = State::Idle;
            break;
        }
    }
    return m_newSamples;
}

void Parser::endLine()
{
    std::string_view line(m_line);
    if (line.back() == '\r')
        line.remove_suffix(1);
    if (line.size() > kMaxLineLength) {
        ++m_stats.tooLong;
        return;
    }
    // marker, body, '*', two hex digits
    if (line.size() < 4 || line[line.size() - 3] != '*') {
        ++m_stats.badSyntax;
        return;
    }
    const int hi = hexValue(line[line.size() - 2]);
    const int lo = hexValue(line[line.size() - 1]);
    if (hi < 0 || lo < 0) {
        ++m_stats.badSyntax;
        return;
    }
    const std::string_view body = line.substr(1, line.size() - 4);
    if (crc8(body) != std::uint8_t(hi * 16 + lo)) {
        ++m_stats.badChecksum;
        return;
    }
    if (line.front() == '$')
        parseSample(body);
    else
        parseIdentification(body);
}

void Parser::parseSample(std::string_view body)
{
    std::array<std::string_view, kMaxChannels + 1> fields;
    const std::size_t n = splitFields(body, fields);
    if (n < 2 || n > fields.size()) {
        ++m_stats.badSyntax;
        return;
    }
    Sample s;
    const auto seq = parseNumber(fields[0], 0, 65535);
    if (!seq) {
        ++m_stats.badSyntax;
        return;
    }
    s.seq = std::uint16_t(*seq);
    s.channels = int(n - 1);
    for (std::size_t i = 1; i < n; ++i) {
        const auto v = parseNumber(fields[i], 0, 65535);
        if (!v) {
            ++m_stats.badSyntax;
            return;
        }
        s.values[i - 1] = std::uint16_t(*v);
    }
    if (m_channels != 0 && s.channels != m_channels) {
        ++m_stats.wrongChannels;
        return;
    }
    m_channels = s.channels;
    // samples missing between the previous good line and this one
    if (m_lastSeq)
        m_stats.lostSamples += std::uint16_t(s.seq - std::uint16_t(*m_lastSeq + 1));
    m_lastSeq = s.seq;
    m_latest = s;
    ++m_stats.goodLines;
    ++m_newSamples;
}

void Parser::parseIdentification(std::string_view body)
{
    std::array<std::string_view, 6> fields;
    const std::size_t n = splitFields(body, fields);
    if (n < 5 || n > 6 || fields[0] != kIdentificationTag) {
        ++m_stats.badSyntax;
        return;
    }
    const auto version = parseNumber(fields[1], kProtocolVersion, kProtocolVersion);
    const auto channels = parseNumber(fields[2], 1, kMaxChannels);
    const auto bits = parseNumber(fields[3], 1, 16);
    const auto rate = parseNumber(fields[4], kMinRate, kMaxRate);
    const std::string_view name = n == 6 ? fields[5] : std::string_view();
    if (!version || !channels || !bits || !rate || !validName(name)) {
        ++m_stats.badSyntax;
        return;
    }
    Identification id;
    id.version = int(*version);
    id.channels = int(*channels);
    id.bits = int(*bits);
    id.rate = int(*rate);
    id.name = std::string(name);  // the only allocation after construction, once per identification
    m_identification = std::move(id);
    m_channels = m_identification->channels;
    // a box that identifies itself has (re)started its sequence
    m_lastSeq.reset();
    ++m_stats.identLines;
}

}  // namespace trainer::daq
