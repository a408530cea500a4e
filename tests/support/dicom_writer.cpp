// SPDX-License-Identifier: Apache-2.0
#include "tests/support/dicom_writer.h"

#include <fstream>
#include <functional>
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
    void pixels(const std::vector<const DicomSliceSpec*>& frames)
    {
        header(0x7FE0, 0x0010, "OW");
        u16(0);
        u32(std::uint32_t(frames.size() * frames.front()->pixels.size() * 2));
        for (const DicomSliceSpec* f : frames) raw(f->pixels.data(), f->pixels.size() * 2);
    }
    /// A sequence and its items, of undefined length (closed by delimiters).
    void sequenceStart(std::uint16_t group, std::uint16_t element)
    {
        header(group, element, "SQ");
        u16(0);
        u32(0xFFFFFFFF);
    }
    void sequenceEnd() { delimiter(0xE0DD); }
    void itemStart()
    {
        u16(0xFFFE);
        u16(0xE000);
        u32(0xFFFFFFFF);
    }
    void itemEnd() { delimiter(0xE00D); }
    /// A sequence of one item holding one element.
    void wrapped(std::uint16_t group, std::uint16_t element, const std::function<void()>& content)
    {
        sequenceStart(group, element);
        itemStart();
        content();
        itemEnd();
        sequenceEnd();
    }

private:
    void delimiter(std::uint16_t element)
    {
        u16(0xFFFE);
        u16(element);
        u32(0);
    }
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

std::string position(const DicomSliceSpec& d) { return decimals({d.position.x(), d.position.y(), d.position.z()}); }
std::string orientation(const DicomSliceSpec& d)
{
    return decimals({d.rowDirection.x(), d.rowDirection.y(), d.rowDirection.z(), d.columnDirection.x(),
                     d.columnDirection.y(), d.columnDirection.z()});
}
std::string pixelSpacing(const DicomSliceSpec& d) { return decimals({d.rowSpacing, d.columnSpacing}); }

/// The 128-byte preamble and the DICM marker every Part 10 file starts with.
void partTenStart(std::ofstream& out)
{
    const std::string preamble(128, '\0');
    out.write(preamble.data(), 128);
    out.write("DICM", 4);
}

/// A classic file holds one frame and its geometry; an enhanced one several, with the geometry in
/// functional groups (orientation and spacing shared, each frame's position its own).
void writeImage(const std::filesystem::path& path, const std::vector<const DicomSliceSpec*>& frames)
{
    const DicomSliceSpec& d = *frames.front();
    const bool enhanced = frames.size() > 1;
    std::ofstream out(path, std::ios::binary);
    partTenStart(out);
    Writer w(out);
    w.text(0x0002, 0x0010, "UI", "1.2.840.10008.1.2.1");                        // explicit VR little endian
    if (enhanced) w.text(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.4.1");  // enhanced MR
    w.text(0x0008, 0x0060, "CS", "MR");
    w.text(0x0018, 0x0050, "DS", decimals({d.sliceThickness}));
    w.text(0x0020, 0x000E, "UI", d.seriesUid);
    w.text(0x0020, 0x0013, "IS", std::to_string(d.instanceNumber));
    if (!enhanced) {
        w.text(0x0020, 0x0032, "DS", position(d));
        w.text(0x0020, 0x0037, "DS", orientation(d));
    }
    w.ushort(0x0028, 0x0002, 1);
    w.text(0x0028, 0x0004, "CS", "MONOCHROME2");
    if (enhanced) w.text(0x0028, 0x0008, "IS", std::to_string(frames.size()));
    w.ushort(0x0028, 0x0010, std::uint16_t(d.rows));
    w.ushort(0x0028, 0x0011, std::uint16_t(d.columns));
    if (!enhanced) w.text(0x0028, 0x0030, "DS", pixelSpacing(d));
    w.ushort(0x0028, 0x0100, 16);
    w.ushort(0x0028, 0x0101, 16);
    w.ushort(0x0028, 0x0102, 15);
    w.ushort(0x0028, 0x0103, 0);
    if (enhanced) {
        w.wrapped(0x5200, 0x9229, [&] {
            w.wrapped(0x0020, 0x9116, [&] { w.text(0x0020, 0x0037, "DS", orientation(d)); });
            w.wrapped(0x0028, 0x9110, [&] { w.text(0x0028, 0x0030, "DS", pixelSpacing(d)); });
        });
        w.sequenceStart(0x5200, 0x9230);
        for (const DicomSliceSpec* f : frames) {
            w.itemStart();
            w.wrapped(0x0020, 0x9113, [&] { w.text(0x0020, 0x0032, "DS", position(*f)); });
            w.itemEnd();
        }
        w.sequenceEnd();
    }
    w.pixels(frames);
}

}  // namespace

void writeDicomSlice(const std::filesystem::path& path, const DicomSliceSpec& slice) { writeImage(path, {&slice}); }

void writeDicomMultiFrame(const std::filesystem::path& path, const std::vector<DicomSliceSpec>& frames)
{
    std::vector<const DicomSliceSpec*> pointers;
    for (const DicomSliceSpec& f : frames) pointers.push_back(&f);
    writeImage(path, pointers);
}

void writeDicomdir(const std::filesystem::path& path, const std::vector<std::string>& images)
{
    std::ofstream out(path, std::ios::binary);
    partTenStart(out);
    Writer w(out);
    w.text(0x0002, 0x0002, "UI", "1.2.840.10008.1.3.10");  // Media Storage Directory Storage
    w.text(0x0002, 0x0010, "UI", "1.2.840.10008.1.2.1");
    w.sequenceStart(0x0004, 0x1220);
    for (const char* type : {"PATIENT", "STUDY", "SERIES"}) {  // the records above the images, as discs have
        w.itemStart();
        w.text(0x0004, 0x1430, "CS", type);
        w.itemEnd();
    }
    for (const std::string& image : images) {
        w.itemStart();
        w.text(0x0004, 0x1430, "CS", "IMAGE");
        w.text(0x0004, 0x1500, "CS", image);
        w.itemEnd();
    }
    w.sequenceEnd();
}

}  // namespace sculpt::test
