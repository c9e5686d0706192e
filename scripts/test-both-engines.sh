# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
## Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
!# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
v# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
## Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
R# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
y# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
P# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
Q# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
F# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
I# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
D# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
B# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
A# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
P# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
O# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
G# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
R# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
U# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
R# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
:# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
## Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
v# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
y# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
Q# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
,# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
P# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
Q# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
,# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
## Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
H# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
P# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
w# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
v# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
P# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
Q# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
## Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
w# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
F# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
I# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
D# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
B# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
A# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
N# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
G# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
I# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
N# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
=# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
,# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
0# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
:# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
{# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
F# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
I# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
D# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
B# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
A# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
P# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
O# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
G# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
R# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
U# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
R# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
:# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
?# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
w# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
}# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
k# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
@# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
## Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
C# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
v# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
;# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
y# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
B# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
w# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
y# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
Q# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
=# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
*# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
j# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
*# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
w# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
\# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
/# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
;# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
[# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
]# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
&# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
&# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
+# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
=# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
(# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
b# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
m# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
f# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
.# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
)# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
n# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
F# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
I# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
D# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
B# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
A# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
L# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
S# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
T# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
N# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
G# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
I# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
N# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
E# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
=# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
a# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
r# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
g# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
-# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
l# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
o# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
c# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
k# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
d# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
{# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
h# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
p# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
_# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
u# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
i# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
t# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
e# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
s# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
[# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
@# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
]# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
}# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
 # Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
$# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
@# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
"# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done

# Compiled above; this only runs them again: every suite that starts a test
# server (tests/common start_server*), browser tests aside.
http_suites=()
for f in $(grep -l 'start_server' tests/*.rs | grep -v '/browser_'); do
  http_suites+=(--test "$(basename "$f" .rs)")
done
