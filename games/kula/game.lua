-- Kula World: the ball's position is not among the known RAM variables, so, as the seed's
-- abstraction did (§3.2.5), the script follows it over the level map from the start square and
-- facing: FORWARD rolls one square, JUMPFORWARD two, LOOKRIGHT/LOOKLEFT turn the view a quarter.
-- Only flat levels (1 and 2) can be described this way.
local FORWARD, LOOKRIGHT, LOOKLEFT, JUMPFORWARD = 0, 1, 2, 3
local PLAYING = 48
local step_x = { [0] = 0, 1, 0, -1 }   -- north, east, south, west
local step_y = { [0] = -1, 0, 1, 0 }

local x, y, facing

function on_reset(level, seed)
  x = nil   -- the map is read when a position is first asked for (visual agents need none)
end

function position()
  if x == nil then
    local _
    _, _, x, y, facing = env.map()
  end
  return x, y, facing
end

function after_move(action)
  if x == nil then return end
  if action == LOOKRIGHT then
    facing = (facing + 1) % 4
  elseif action == LOOKLEFT then
    facing = (facing + 3) % 4
  else
    local n = action == JUMPFORWARD and 2 or 1
    x = x + n * step_x[facing]
    y = y + n * step_y[facing]
  end
end
