#pragma once
// A typed blackboard: one value per type, so a frame's trunk publishes its handles (G-buffer, lit
// colour, reflection, ...) as small structs and consumers look them up by type, without the trunk
// knowing who reads them (Filament fg/Blackboard, skaarj1989/FrameGraph FrameGraphBlackboard).
#include <any>
#include <stdexcept>
#include <string>
#include <typeindex>
#include <unordered_map>

namespace ppr::graph {

class Blackboard {
public:
    template <class T>
    void put(T value) {
        entries_[std::type_index(typeid(T))] = std::move(value);
    }
    template <class T>
    bool has() const {
        return entries_.count(std::type_index(typeid(T))) != 0;
    }
    // Null when nothing of type T was published.
    template <class T>
    const T* find() const {
        auto it = entries_.find(std::type_index(typeid(T)));
        return it == entries_.end() ? nullptr : std::any_cast<T>(&it->second);
    }
    // Throws std::logic_error naming the type when nothing of type T was published.
    template <class T>
    const T& get() const {
        if (const T* v = find<T>()) return *v;
        throw std::logic_error(std::string("blackboard: nothing published of type ") + typeid(T).name());
    }
    template <class T>
    void erase() {
        entries_.erase(std::type_index(typeid(T)));
    }

private:
    std::unordered_map<std::type_index, std::any> entries_;
};

}  // namespace ppr::graph
