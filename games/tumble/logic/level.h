/* Level maps: the compiled form of the text maps in games/tumble/levels/ (tools/levelc.c turns
   them into levels_data.c at build time) and the tile/item codes the rules use. */
#ifndef TUMBLE_LEVEL_H
#define TUMBLE_LEVEL_H
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

#define LEVEL_MAX_W 16
#define LEVEL_MAX_H 16

/* Map characters (see README.md): '.' or ' ' no tile, '#' floor, 'S' start, 'E' exit, '^' spikes,
   '%' crumbling floor, 'c' coin, 'f' fruit, 'k' key (items lie on floor). */
enum Tile { TILE_VOID = 0, TILE_FLOOR = 1, TILE_EXIT = 2, TILE_SPIKES = 3, TILE_CRUMBLE = 4 };
enum Item { ITEM_NONE = 0, ITEM_COIN = 1, ITEM_FRUIT = 2, ITEM_KEY = 3 };

#define SCORE_COIN 250
#define SCORE_FRUIT 500
#define SCORE_KEY 1000

typedef struct LevelDef {
  const char *name;
  uint8_t width, height;
  uint16_t time_seconds;
  uint8_t start_x, start_y, start_facing;
  const char *cells; /* width*height map characters, row by row, north row first */
} LevelDef;

extern const LevelDef tumble_levels[];
extern const int tumble_level_count;

/* Decodes one map character into tile and item; returns 0 for a character maps may not use. */
int level_decode_cell(char c, uint8_t *tile, uint8_t *item);
/* Score of an item code. */
uint32_t level_item_score(uint8_t item);

#ifdef __cplusplus
}
#endif

#endif
