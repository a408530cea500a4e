// SPDX-License-Identifier: Apache-2.0
#include "core/io/threemf_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/io/stored_zip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

namespace sculpt {

namespace {

const char* const kContentTypes =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">"
    "<Default Extension=\"rels\" ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>"
    "<Default Extension=\"model\" ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/>"
    "</Types>\n";

const char* const kRelationships =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">"
    "<Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
    "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/>"
    "</Relationships>\n";

/// Text for an XML attribute value.
std::string escaped(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string hexColour(const openvdb::Vec3f& c)
{
    const auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    char text[8];
    std::snprintf(text, sizeof text, "#%02X%02X%02X", byte(c[0]), byte(c[1]), byte(c[2]));
    return text;
}

/// One object's <mesh>: "%.9g" gives every float back exactly.
void appendMesh(std::string& xml, const TriangleMesh& mesh, MeshFrame frame)
{
    const float flip = frame == MeshFrame::Ras ? -1.0f : 1.0f;  // a half turn about z: windings kept
    char line[128];
    xml += "<mesh><vertices>\n";
    for (const auto& p : mesh.positions) {
        std::snprintf(line, sizeof line, "<vertex x=\"%.9g\" y=\"%.9g\" z=\"%.9g\"/>\n", double(flip * p[0]),
                      double(flip * p[1]), double(p[2]));
        xml += line;
    }
    xml += "</vertices><triangles>\n";
    for (const auto& t : mesh.triangles) {
        std::snprintf(line, sizeof line, "<triangle v1=\"%u\" v2=\"%u\" v3=\"%u\"/>\n", unsigned(t[0]), unsigned(t[1]),
                      unsigned(t[2]));
        xml += line;
    }
    xml += "</triangles></mesh>\n";
}

std::string modelXml(const std::vector<ThreeMfObject>& objects, const std::string& unit, MeshFrame frame)
{
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"" + unit +
                      "\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n"
                      "<metadata name=\"Application\">sculpt</metadata>\n"
                      "<metadata name=\"Description\">" +
                      escaped(meshFrameTag(frame)) + "</metadata>\n<resources>\n<basematerials id=\"1\">\n";
    for (const ThreeMfObject& object : objects)
        xml += "<base name=\"" + escaped(object.name) + "\" displaycolor=\"" + hexColour(object.colour) + "\"/>\n";
    xml += "</basematerials>\n";
    for (std::size_t i = 0; i < objects.size(); ++i) {
        xml += "<object id=\"" + std::to_string(i + 2) + "\" type=\"model\" name=\"" + escaped(objects[i].name) +
               "\" pid=\"1\" pindex=\"" + std::to_string(i) + "\">\n";
        appendMesh(xml, *objects[i].mesh, frame);
        xml += "</object>\n";
    }
    xml += "</resources>\n<build>\n";
    for (std::size_t i = 0; i < objects.size(); ++i) xml += "<item objectid=\"" + std::to_string(i + 2) + "\"/>\n";
    return xml + "</build>\n</model>\n";
}

}  // namespace

std::string threeMfUnit(const std::string& units, const std::filesystem::path& file)
{
    static const std::array<std::pair<const char*, const char*>, 14> kUnits{{{"mm", "millimeter"},
                                                                             {"millimeter", "millimeter"},
                                                                             {"millimetre", "millimeter"},
                                                                             {"um", "micron"},
                                                                             {"micron", "micron"},
                                                                             {"cm", "centimeter"},
                                                                             {"centimeter", "centimeter"},
                                                                             {"centimetre", "centimeter"},
                                                                             {"m", "meter"},
                                                                             {"meter", "meter"},
                                                                             {"metre", "meter"},
                                                                             {"in", "inch"},
                                                                             {"inch", "inch"},
                                                                             {"ft", "foot"}}};
    for (const auto& [name, unit] : kUnits)
        if (units == name) return unit;
    throw InputError(file.string() + ": 3MF has no unit '" + units + "' (it knows mm, um, cm, m, in and ft)");
}

void writeThreeMf(const std::vector<ThreeMfObject>& objects, const std::filesystem::path& path,
                  const std::string& units, MeshFrame frame)
{
    const std::string unit = threeMfUnit(units, path);
    double bytes = 0.0;
    for (const ThreeMfObject& object : objects) {
        if (!object.mesh->finite()) throw InputError(path.string() + ": a vertex is not a finite number: not written");
        bytes += 64.0 * double(object.mesh->positions.size()) + 48.0 * double(object.mesh->triangles.size());
    }
    requireMemory(2.0 * bytes, path.string() + " (its XML)");
    AtomicFile out(path);
    writeStoredZip({{"[Content_Types].xml", kContentTypes},
                    {"_rels/.rels", kRelationships},
                    {"3D/3dmodel.model", modelXml(objects, unit, frame)}},
                   out.temporaryPath());
    out.commit();
}

}  // namespace sculpt
