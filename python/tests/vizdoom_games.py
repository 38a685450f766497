"""A helper the Python tests share (pytest puts this folder on the path)."""

import sightline.vizdoom as vzd


def open_game(cfg: str, seed: int = 3, **settings) -> vzd.DoomGame:
    """A started `DoomGame` of `cfg`, seeded `seed`, each keyword a setter
    (`audio_buffer_enabled=True` calls `set_audio_buffer_enabled(True)`)."""
    game = vzd.DoomGame()
    game.load_config(cfg)
    for key, value in settings.items():
        getattr(game, f"set_{key}")(value)
    game.set_seed(seed)
    game.init()
    return game
