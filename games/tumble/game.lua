-- Tumble: what the manifest cannot say. The game's only randomness (how long a crumbling tile
-- lasts) comes from the xorshift32 state in the contract; an episode's seed sets it.
function on_reset(level, seed)
  -- xorshift32 must never hold 0: it would stay 0 for ever.
  env.set("rng", seed ~= 0 and seed or 0x2545F491)
end
