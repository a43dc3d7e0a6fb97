# Sourced by the CLI tests: `expect` runs a command and checks its exit status and output; failures counts the
# checks that did not hold.
failures=0

expect() { # expect NAME EXPECTED_STATUS MESSAGE_PATTERN -- command...
    local name=$1 status=$2 pattern=$3
    shift 4
    local output
    output=$("$@" 2>&1)
    local actual=$?
    if [[ $actual -ne $status ]] || ! grep -qE -e "$pattern" <<<"$output"; then
        echo "FAIL $name: status $actual (wanted $status), output:"
        echo "$output"
        failures=$((failures + 1))
    else
        echo "ok   $name"
    fi
}
