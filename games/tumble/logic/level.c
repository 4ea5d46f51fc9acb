/* Map character decoding and item values, shared by the game and the build-time level compiler. */
#include "level.h"

int level_decode_cell(char c, uint8_t *tile, uint8_t *item) {
  *item = ITEM_NONE;
  switch (c) {
    case '.': case ' ': *tile = TILE_VOID; return 1;
    case '#': case 'S': *tile = TILE_FLOOR; return 1;
    case 'E': *tile = TILE_EXIT; return 1;
    case '^': *tile = TILE_SPIKES; return 1;
    case '%': *tile = TILE_CRUMBLE; return 1;
    case 'c': *tile = TILE_FLOOR; *item = ITEM_COIN; return 1;
    case 'f': *tile = TILE_FLOOR; *item = ITEM_FRUIT; return 1;
    case 'k': *tile = TILE_FLOOR; *item = ITEM_KEY; return 1;
    default: *tile = TILE_VOID; return 0;
  }
}

uint32_t level_item_score(uint8_t item) {
  switch (item) {
    case ITEM_COIN: return SCORE_COIN;
    case ITEM_FRUIT: return SCORE_FRUIT;
    case ITEM_KEY: return SCORE_KEY;
    default: return 0;
  }
}
