// An SVG read back with expat, for the tests of the drawings (export/tests, tests/cli): every
// element with its attributes, text and enclosing groups.
#pragma once

#include <expat.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace hlr::test {

struct SvgElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string group;                // id of the nearest enclosing <g>, if any
  std::vector<std::string> groups;  // ids of every enclosing <g>, outermost first
  std::string text;
};

struct SvgDocument {
  bool well_formed = false;
  std::string error;
  std::vector<SvgElement> elements;
  std::vector<std::size_t> open;  // stack of indices into elements

  const SvgElement* find(const std::string& name, const std::string& id) const {
    for (const auto& e : elements)
      if (e.name == name && e.attributes.count("id") && e.attributes.at("id") == id) return &e;
    return nullptr;
  }
  // Elements `name` anywhere inside the group with id `group`.
  std::vector<const SvgElement*> in_group(const std::string& name, const std::string& group) const {
    std::vector<const SvgElement*> out;
    for (const auto& e : elements)
      if (e.name == name && std::find(e.groups.begin(), e.groups.end(), group) != e.groups.end()) out.push_back(&e);
    return out;
  }
  std::ptrdiff_t position(const std::string& name, const std::string& id) const {
    const SvgElement* e = find(name, id);
    return e ? e - elements.data() : -1;
  }
};

inline SvgDocument parse_svg(const std::string& text) {
  SvgDocument doc;
  XML_Parser parser = XML_ParserCreate("UTF-8");
  XML_SetUserData(parser, &doc);
  XML_SetElementHandler(
      parser,
      [](void* data, const XML_Char* name, const XML_Char** attributes) {
        auto& d = *static_cast<SvgDocument*>(data);
        SvgElement e;
        e.name = name;
        for (int i = 0; attributes[i]; i += 2) e.attributes[attributes[i]] = attributes[i + 1];
        for (std::size_t i : d.open)
          if (d.elements[i].name == "g") e.groups.push_back(d.elements[i].attributes["id"]);
        if (!e.groups.empty()) e.group = e.groups.back();
        d.open.push_back(d.elements.size());
        d.elements.push_back(std::move(e));
      },
      [](void* data, const XML_Char*) { static_cast<SvgDocument*>(data)->open.pop_back(); });
  XML_SetCharacterDataHandler(parser, [](void* data, const XML_Char* s, int len) {
    auto& d = *static_cast<SvgDocument*>(data);
    if (!d.open.empty()) d.elements[d.open.back()].text.append(s, len);
  });
  doc.well_formed = XML_Parse(parser, text.data(), static_cast<int>(text.size()), 1) == XML_STATUS_OK;
  if (!doc.well_formed) doc.error = XML_ErrorString(XML_GetErrorCode(parser));
  XML_ParserFree(parser);
  return doc;
}

}  // namespace hlr::test
