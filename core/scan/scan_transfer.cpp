// SPDX-License-Identifier: Apache-2.0
#include "core/scan/scan_transfer.h"

#include "core/scan/vtk_image_scan.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <cstring>
#include <stdexcept>

namespace sculpt {

namespace {

/// The header's fields, written and read in one order.
class HeaderWriter {
public:
    template <typename T>
    void put(const T& value)
    {
        mBytes.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    void put(const std::string& text)
    {
        put(std::uint64_t(text.size()));
        mBytes += text;
    }
    std::string take() { return std::move(mBytes); }

private:
    std::string mBytes;
};

class HeaderReader {
public:
    explicit HeaderReader(const std::string& bytes) : mBytes(bytes) {}

    template <typename T>
    T get()
    {
        T value;
        std::memcpy(&value, take(sizeof value), sizeof value);
        return value;
    }
    std::string getString()
    {
        const auto size = get<std::uint64_t>();
        return std::string(take(size), size);
    }

private:
    const char* take(std::size_t bytes)
    {
        if (bytes > mBytes.size() - mAt) throw std::runtime_error("a scan's transfer header is cut short");
        mAt += bytes;
        return mBytes.data() + mAt - bytes;
    }

    const std::string& mBytes;
    std::size_t mAt = 0;
};

}  // namespace

ChildReply packScan(const ScanVolume& scan)
{
    vtkImageData* image = scan.mImpl->image;
    HeaderWriter header;
    const openvdb::Coord dims = scan.dims();
    for (int a = 0; a < 3; ++a) header.put(std::int32_t(dims[a]));
    header.put(std::int32_t(image->GetScalarType()));
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) header.put(scan.worldFromIndex()[r][c]);
    }
    header.put(scan.source());
    header.put(std::uint64_t(scan.warnings().size()));
    for (const std::string& warning : scan.warnings()) header.put(warning);
    return ChildReply{header.take(), image->GetScalarPointer(), scan.denseBytes(), scan.mImpl};
}

ScanVolume unpackScan(IsolatedBytes bytes)
{
    HeaderReader header(bytes.header);
    int dims[3];
    for (int& d : dims) d = header.get<std::int32_t>();
    const auto type = header.get<std::int32_t>();
    openvdb::Mat4d worldFromIndex;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) worldFromIndex[r][c] = header.get<double>();
    }
    const std::string source = header.getString();
    std::vector<std::string> warnings(header.get<std::uint64_t>());
    for (std::string& warning : warnings) warning = header.getString();

    vtkSmartPointer<vtkDataArray> samples = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
    const vtkIdType count = vtkIdType(dims[0]) * dims[1] * dims[2];
    if (!samples || bytes.bodyBytes != std::size_t(count) * std::size_t(samples->GetDataTypeSize()))
        throw std::runtime_error("a scan's transfer body does not match its header");
    samples->SetVoidArray(bytes.body.release(), count, /*save=*/0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(dims);
    image->GetPointData()->SetScalars(samples);
    return makeScan(image, worldFromIndex, source, std::move(warnings));
}

}  // namespace sculpt
