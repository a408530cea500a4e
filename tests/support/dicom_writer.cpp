#include "tests/support/dicom_writer.h"

#include <fstream>
#include <sstream>

namespace sculpt::test {

namespace {

class Writer {
public:
    explicit Writer(std::ofstream& out) : mOut(out) {}

    void raw(const void* data, size_t bytes) { mOut.write(static_cast<const char*>(data), std::streamsize(bytes)); }
    void u16(std::uint16_t v) { raw(&v, 2); }
    void u32(std::uint32_t v) { raw(&v, 4); }

    /// A short-form element (2-byte length); text padded to even length as DICOM requires.
    void text(std::uint16_t group, std::uint16_t element, const char vr[2], std::string value)
    {
        if (value.size() % 2) value += (std::string(vr) == "UI") ? '\0' : ' ';
        header(group, element, vr);
        u16(std::uint16_t(value.size()));
        raw(value.data(), value.size());
    }
    void ushort(std::uint16_t group, std::uint16_t element, std::uint16_t value)
    {
        header(group, element, "US");
        u16(2);
        u16(value);
    }
    void pixels(const std::vector<std::uint16_t>& values)
    {
        header(0x7FE0, 0x0010, "OW");
        u16(0);
        u32(std::uint32_t(values.size() * 2));
        raw(values.data(), values.size() * 2);
    }

private:
    void header(std::uint16_t group, std::uint16_t element, const char vr[2])
    {
        u16(group);
        u16(element);
        raw(vr, 2);
    }
    std::ofstream& mOut;
};

std::string decimals(std::initializer_list<double> values)
{
    std::ostringstream s;
    s.precision(10);
    bool first = true;
    for (double v : values) {
        s << (first ? "" : "\\") << v;
        first = false;
    }
    return s.str();
}

}  // namespace

void writeDicomSlice(const std::filesystem::path& path, const DicomSliceSpec& d)
{
    std::ofstream out(path, std::ios::binary);
    const std::string preamble(128, '\0');
    out.write(preamble.data(), 128);
    out.write("DICM", 4);
    Writer w(out);
    w.text(0x0002, 0x0010, "UI", "1.2.840.10008.1.2.1");  // explicit VR little endian
    w.text(0x0008, 0x0060, "CS", "MR");
    w.text(0x0018, 0x0050, "DS", decimals({d.sliceThickness}));
    w.text(0x0020, 0x000E, "UI", d.seriesUid);
    w.text(0x0020, 0x0013, "IS", std::to_string(d.instanceNumber));
    w.text(0x0020, 0x0032, "DS", decimals({d.position.x(), d.position.y(), d.position.z()}));
    w.text(0x0020, 0x0037, "DS",
           decimals({d.rowDirection.x(), d.rowDirection.y(), d.rowDirection.z(), d.columnDirection.x(),
                     d.columnDirection.y(), d.columnDirection.z()}));
    w.ushort(0x0028, 0x0002, 1);
    w.text(0x0028, 0x0004, "CS", "MONOCHROME2");
    w.ushort(0x0028, 0x0010, std::uint16_t(d.rows));
    w.ushort(0x0028, 0x0011, std::uint16_t(d.columns));
    w.text(0x0028, 0x0030, "DS", decimals({d.rowSpacing, d.columnSpacing}));
    w.ushort(0x0028, 0x0100, 16);
    w.ushort(0x0028, 0x0101, 16);
    w.ushort(0x0028, 0x0102, 15);
    w.ushort(0x0028, 0x0103, 0);
    w.pixels(d.pixels);
}

}  // namespace sculpt::test
