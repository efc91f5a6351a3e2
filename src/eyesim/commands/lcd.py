"""RoBIOS LCD group: text, colours, fonts, modes, the soft-key menu, graphics and images."""

from eyesim.commands.errors import checked_arguments, require
from eyesim.robot.components.lcd import HEIGHT, WIDTH, Lcd


def _lcd(robot) -> Lcd:
    return require(robot.component(Lcd), robot, "LCD")


def lcd_printf(sim, robot, request):
    (text,) = request.args
    _lcd(robot).print(text)
    return (0,)


def lcd_set_printf(sim, robot, request):
    row, column, text = request.args
    lcd = _lcd(robot)
    with checked_arguments():
        lcd.set_position(row, column)
    lcd.print(text)
    return (0,)


def lcd_clear(sim, robot, request):
    _lcd(robot).clear()
    return (0,)


def lcd_set_pos(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_position(*request.args)
    return (0,)


def lcd_get_pos(sim, robot, request):
    lcd = _lcd(robot)
    return (0, lcd.row, lcd.column)


def lcd_set_color(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_color(*request.args)
    return (0,)


def lcd_set_font(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_font(*request.args)
    return (0,)


def lcd_set_font_size(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_font_size(*request.args)
    return (0,)


def lcd_set_mode(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_mode(*request.args)
    sim.events.menu(robot)  # the viewer needs to know whether the menu bar shows, and which way up
    return (0,)


def lcd_menu(sim, robot, request):
    _lcd(robot).set_menu(list(request.args))
    sim.events.menu(robot)
    return (0,)


def lcd_menu_i(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_menu_entry(*request.args)
    sim.events.menu(robot)
    return (0,)


def lcd_get_size(sim, robot, request):
    _lcd(robot)
    return (0, WIDTH, HEIGHT)


def lcd_pixel(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_pixel(*request.args)
    return (0,)


def lcd_get_pixel(sim, robot, request):
    with checked_arguments():
        return (_lcd(robot).pixel(*request.args),)


def lcd_line(sim, robot, request):
    with checked_arguments():
        _lcd(robot).line(*request.args)
    return (0,)


def lcd_area(sim, robot, request):
    x1, y1, x2, y2, color, fill = request.args
    with checked_arguments():
        _lcd(robot).area(x1, y1, x2, y2, color, bool(fill))
    return (0,)


def lcd_circle(sim, robot, request):
    x, y, radius, color, fill = request.args
    with checked_arguments():
        _lcd(robot).circle(x, y, radius, color, bool(fill))
    return (0,)


def lcd_image(sim, robot, request):
    with checked_arguments():
        _lcd(robot).image(*request.args)
    return (0,)


def lcd_refresh(sim, robot, request):
    _lcd(robot).refresh()
    return (0,)


HANDLERS = {
    "LCD_PRINTF": lcd_printf,
    "LCD_SET_PRINTF": lcd_set_printf,
    "LCD_CLEAR": lcd_clear,
    "LCD_MENU": lcd_menu,
    "LCD_SET_POS": lcd_set_pos,
    "LCD_GET_POS": lcd_get_pos,
    "LCD_SET_COLOR": lcd_set_color,
    "LCD_SET_FONT": lcd_set_font,
    "LCD_SET_FONT_SIZE": lcd_set_font_size,
    "LCD_SET_MODE": lcd_set_mode,
    "LCD_MENU_I": lcd_menu_i,
    "LCD_GET_SIZE": lcd_get_size,
    "LCD_PIXEL": lcd_pixel,
    "LCD_GET_PIXEL": lcd_get_pixel,
    "LCD_LINE": lcd_line,
    "LCD_AREA": lcd_area,
    "LCD_CIRCLE": lcd_circle,
    "LCD_IMAGE": lcd_image,
    "LCD_REFRESH": lcd_refresh,
}
