"""Edits of a copied tutorial for the validation scripts: each replacement
must find its text, so that a tutorial changed under a script stops it
with the file and the text instead of building a different case.

    edit(path, pairs, regex=False)   replace each (old, new) of pairs
    bodyFrameInflow(case, V)         0.orig/U and 0.orig/p of the body
                                     frame: the walls and the inlet at
                                     (0 V 0), an outlet (inletOutlet U,
                                     p = 0); the mesh needs the patches
                                     walls, inlet and outlet
"""
import re
import sys


def edit(path, pairs, regex=False):
    s = open(path).read()
    for a, b in pairs:
        n = len(re.findall(a, s)) if regex else s.count(a)
        if n == 0:
            sys.exit("%s: '%s' not found in %s"
                     % (sys.argv[0].split("/")[-1], a, path))
        s = re.sub(a, b, s) if regex else s.replace(a, b)
    open(path, 'w').write(s)


def bodyFrameInflow(case, V):
    edit(case + "/0.orig/U", [
        ("internalField   uniform (0 0 0);",
         "internalField   uniform (0 %s 0);" % V),
        ("    walls\n    {\n        type            noSlip;\n    }",
         "    \"(walls|inlet)\"\n    {\n        type            fixedValue;\n"
         "        value           uniform (0 %s 0);\n    }\n"
         "    outlet\n    {\n        type            inletOutlet;\n"
         "        inletValue      uniform (0 0 0);\n"
         "        value           uniform (0 %s 0);\n    }" % (V, V))])
    edit(case + "/0.orig/p", [
        ("    walls\n    {\n        type            zeroGradient;\n    }",
         "    \"(walls|inlet)\"\n    {\n        type            zeroGradient;\n"
         "    }\n    outlet\n    {\n        type            fixedValue;\n"
         "        value           uniform 0;\n    }")])
