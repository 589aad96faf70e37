# Split a GNU ld map file's allocated sections by origin. Prints
#   "<output section> <core|fw|ws|lib|fill> <bytes>" (summed), and
#   "sym <output section> <input section> <bytes>" for each core input section.
# Origin from the object path: .../core/*.o or .../core/MODULE/*.o is the engine, .../fw/*.o the
# firmware (.bss.fw_ws, the workspace, apart), archives the C library/libgcc.
function hex(s,    i, n) {
    s = tolower(s); sub(/^0x/, "", s); n = 0
    for (i = 1; i <= length(s); i++) n = n * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
    return n
}
function add(name, size, file,    cat) {
    if (!(out in keep) || size == 0) return
    if (name == "*fill*") cat = "fill"
    else if (name == ".bss.fw_ws") cat = "ws"
    else if (file ~ /\/core\/([^\/]*\/)?[^\/]*\.o$/) cat = "core"
    else if (file ~ /\/fw\/[^\/]*\.o$/) cat = "fw"
    else if (file ~ /\.a\(/) cat = "lib"
    else cat = "other"
    sum[out " " cat] += size
    if (cat == "core") print "sym", out, name, size
}
BEGIN { keep[".text"]; keep[".rodata"]; keep[".ARM.exidx"]; keep[".data"]; keep[".bss"]; keep[".framebuffer"] }
/^Linker script and memory map/ { inmap = 1; next }
!inmap { next }
/^[^ ]/ { out = $1; pend = ""; next }                 # output section
pend != "" && $1 ~ /^0x/ && $2 ~ /^0x/ && NF == 3 { add(pend, hex($2), $3); pend = ""; next }
{ pend = "" }
/^ [^ ]/ && $1 !~ /^\*\(/ && $1 !~ /^(KEEP|SORT)/ {  # input section
    if (NF >= 3 && $2 ~ /^0x/ && $3 ~ /^0x/) add($1, hex($3), $4)
    else if (NF == 1) pend = $1
}
END { for (k in sum) print k, sum[k] }
