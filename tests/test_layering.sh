#!/usr/bin/env bash
# test_layering.sh: the tree's layering rules, checked on the sources.
#   1. engine/ names no variant (the registry's names, read from variants/*/);
#   2. a variant includes engine headers and its own, never another variant's;
#   3. every variant folder has a README.md;
#   4. the README's counter table is what the declarations give.
set -u
cd "$(dirname "$0")/.."
fail=0
variants=$(ls -d variants/*/ | xargs -n1 basename)
[ -n "$variants" ] || { echo "layering: no variant folders found"; exit 1; }
for v in $variants; do
  if grep -rniw -- "$v" engine/; then
    echo "layering: engine/ names the variant '$v' (above)"; fail=1
  fi
  [ -f "variants/$v/README.md" ] || { echo "layering: variants/$v has no README.md"; fail=1; }
  for other in $variants; do
    [ "$other" = "$v" ] && continue
    if grep -n "#include \"\(\.\./\)\?$other/" variants/"$v"/*.[ch]; then
      echo "layering: variant $v includes a header of variant $other (above)"; fail=1
    fi
    for h in variants/"$other"/*.h; do
      [ -f "$h" ] || continue
      b=$(basename "$h")
      [ -f "variants/$v/$b" ] && continue   # its own header of the same name
      if grep -n "#include \"$b\"" variants/"$v"/*.[ch]; then
        echo "layering: variant $v includes $other's $b (above)"; fail=1
      fi
    done
  done
done
/usr/bin/python3 scripts/counter_table.py --check || fail=1
[ "$fail" -eq 0 ] && echo "layering: ok ($(echo $variants | wc -w) variants)"
exit "$fail"
