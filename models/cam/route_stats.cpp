#include "cam/route_stats.hpp"

namespace cnc::cam {

RouteStats route_stats(const std::vector<Entity>& entities, const std::vector<Route>& routes, geom::Vec2 start_mm) {
    RouteStats st;
    st.routes = static_cast<int>(routes.size());
    st.rapid_mm = rapid_length_mm(entities, routes, start_mm);
    for (const Route& r : routes) {
        st.moves += static_cast<int>(r.size());
        for (const Step& s : r) st.cut_mm += entities.at(static_cast<std::size_t>(s.entity)).path.length_mm();
    }
    return st;
}

}  // namespace cnc::cam
