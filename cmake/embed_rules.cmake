# SPDX-License-Identifier: GPL-2.0-or-later
# Writes a C++ file that holds every rules/*.rules file as a string:
# the binary needs no files at run time.
set(out "// Generated from rules/*.rules by cmake/embed_rules.cmake; do not edit.\n")
string(APPEND out "#include \"algebra/rules.h\"\n\nnamespace lagrange {\n\n")
string(APPEND out "const std::vector<embedded_rule_file>& embedded_rule_files()\n{\n")
string(APPEND out "    static const std::vector<embedded_rule_file> files = {\n")
list(SORT INPUTS)
foreach(f ${INPUTS})
  get_filename_component(name ${f} NAME)
  file(READ ${f} text)
  string(APPEND out "        {\"${name}\", R\"lagrange_rules(${text})lagrange_rules\"},\n")
endforeach()
string(APPEND out "    };\n    return files;\n}\n\n} // namespace lagrange\n")
file(WRITE ${OUTPUT} "${out}")
