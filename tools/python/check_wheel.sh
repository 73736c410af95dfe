"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
!"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
H"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
A"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
`"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
`"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
*"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
`"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
`"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
<"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
>"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
V"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
N"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
V"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
X"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
R"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
A"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
V"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
N"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
V"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
X"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
R"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
A"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
#"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
J"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
B"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
j"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
&"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
&"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
X"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
+"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
B"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
U"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
G"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
N"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
A"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
H"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
B"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
U"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
Y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
H"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
N"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
A"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
H"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
J"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
B"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
M"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
D"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
E"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
L"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
I"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
T"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
J"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
O"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
B"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
q"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
q"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
q"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
<"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
<"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
Y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
'"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
+"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
\"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
<"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
+"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
["$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
]"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
6"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
6"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
4"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
6"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
>"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
S"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
0"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
<"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
5"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
k"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
%"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
,"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
P"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
Y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
q"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
="$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
*"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
*"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
*"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
*"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
3"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
<"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
>"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
>"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
&"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
z"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
q"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
>"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
&"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
z"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
f"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
-"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
q"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
v"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
/"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
_"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
."$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
|"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
{"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
>"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
&"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
2"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
x"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
1"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
;"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
}"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
c"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
:"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
("$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
m"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
$"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
w"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
)"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
o"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
b"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
r"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
y"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
a"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
d"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
t"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
h"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
e"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
 "$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
p"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
l"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
u"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
g"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
i"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
n"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
s"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
""$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }

"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
grep -q "modesplit/_native/libmodesplit.so" "$tmp/listing" ||
    { echo "wheel: no libmodesplit.so inside $whl" >&2; exit 1; }
grep -q "modesplit/_native/modesplit/plugins/shape_sphere.so" "$tmp/listing" ||
    { echo "wheel: no plugins inside $whl" >&2; exit 1; }
