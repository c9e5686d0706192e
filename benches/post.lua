-- wrk script: POST the JSON file named by $BODY_FILE to the path given after `--`,
-- and count any answer that is not the expected status as an error.
local path, expected

function init(args)
  path = args[1] or "/api/v1/solve"
  expected = tonumber(args[2] or "200")
  local f = assert(io.open(os.getenv("BODY_FILE"), "rb"))
  local body = f:read("*a")
  f:close()
  req = wrk.format("POST", path, { ["Content-Type"] = "application/json" }, body)
end

function request()
  return req
end

local unexpected = 0
function response(status, headers, body)
  if status ~= expected then
    unexpected = unexpected + 1
    if unexpected <= 3 then io.stderr:write("unexpected status " .. status .. ": " .. body .. "\n") end
  end
end
