// SPDX-License-Identifier: Apache-2.0
#include "tests/support/threemf_reader.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <algorithm>

namespace sculpt::test {

namespace {

using namespace NMR;

/// lib3mf's objects are reference counted by hand: released at scope exit.
template <typename T>
struct Owned {
    T* p = nullptr;
    ~Owned()
    {
        if (p) lib3mf_release(p);
    }
};

ThreeMfModel::Object objectOf(PLib3MFModel* model, PLib3MFModelResource* resource)
{
    ThreeMfModel::Object object;
    char name[256] = {};
    ULONG needed = 0;
    lib3mf_object_getnameutf8(resource, name, sizeof name, &needed);
    object.name = name;
    DWORD vertices = 0, triangles = 0;
    lib3mf_meshobject_getvertexcount(resource, &vertices);
    lib3mf_meshobject_gettrianglecount(resource, &triangles);
    object.vertices = vertices;
    object.triangles = triangles;
    std::vector<MODELMESHVERTEX> positions(vertices);
    lib3mf_meshobject_getvertices(resource, positions.data(), vertices, nullptr);
    object.minZ = 1e300;
    object.maxZ = -1e300;
    for (const MODELMESHVERTEX& v : positions) {
        object.minZ = std::min(object.minZ, double(v.m_fPosition[2]));
        object.maxZ = std::max(object.maxZ, double(v.m_fPosition[2]));
    }
    Owned<PLib3MFDefaultPropertyHandler> properties;
    DWORD group = 0, index = 0;
    Owned<PLib3MFModelBaseMaterial> material;
    BYTE rgba[4] = {};
    if (lib3mf_object_createdefaultpropertyhandler(resource, &properties.p) == LIB3MF_OK &&
        lib3mf_defaultpropertyhandler_getbasematerial(properties.p, &group, &index) == LIB3MF_OK &&
        lib3mf_model_getbasematerialbyid(model, group, &material.p) == LIB3MF_OK &&
        lib3mf_basematerial_getdisplaycolor(material.p, index, &rgba[0], &rgba[1], &rgba[2], &rgba[3]) == LIB3MF_OK)
        object.colour = {rgba[0], rgba[1], rgba[2]};
    return object;
}

}  // namespace

ThreeMfModel readThreeMf(const std::filesystem::path& path)
{
    ThreeMfModel result;
    Owned<PLib3MFModel> model;
    Owned<PLib3MFModelReader> reader;
    if (lib3mf_createmodel(&model.p) != LIB3MF_OK || lib3mf_model_queryreader(model.p, "3mf", &reader.p) != LIB3MF_OK ||
        lib3mf_reader_readfromfileutf8(reader.p, path.c_str()) != LIB3MF_OK)
        return result;
    result.read = true;
    DWORD unit = 0;
    lib3mf_model_getunit(model.p, &unit);
    result.unit = int(unit);
    Owned<PLib3MFModelResourceIterator> objects;
    lib3mf_model_getmeshobjects(model.p, &objects.p);
    BOOL more = false;
    while (lib3mf_resourceiterator_movenext(objects.p, &more) == LIB3MF_OK && more) {
        Owned<PLib3MFModelResource> resource;
        lib3mf_resourceiterator_getcurrent(objects.p, &resource.p);
        result.objects.push_back(objectOf(model.p, resource.p));
    }
    Owned<PLib3MFModelBuildItemIterator> items;
    lib3mf_model_getbuilditems(model.p, &items.p);
    while (lib3mf_builditemiterator_movenext(items.p, &more) == LIB3MF_OK && more) ++result.buildItems;
    return result;
}

}  // namespace sculpt::test
